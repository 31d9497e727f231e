package org.hapticon.sensor.serial

/** bmRequestType values (USB 2.0 §9.3): direction bit 7, type bits 5..6, recipient bits 0..4. */
internal object UsbRequestType {
    const val STANDARD_DEVICE_IN = 0x80
    const val CLASS_INTERFACE_OUT = 0x21
    const val VENDOR_DEVICE_OUT = 0x40
    const val VENDOR_DEVICE_IN = 0xC0
    const val VENDOR_INTERFACE_OUT = 0x41
}

/** USB class codes used when probing. */
internal object UsbClass {
    const val CDC_COMMUNICATIONS = 0x02
    const val CDC_DATA = 0x0A
    const val CDC_SUBCLASS_ACM = 0x02
    const val VENDOR_SPECIFIC = 0xFF
}

/** Timeout for configuration requests: chips answer in a few ms, a stuck one should fail visibly. */
internal const val CONTROL_TIMEOUT_MILLIS = 1000

/** A 32-bit value as 4 little-endian bytes, the byte order of every USB field. */
internal fun littleEndian32(value: Int): ByteArray =
    byteArrayOf(value.toByte(), (value shr 8).toByte(), (value shr 16).toByte(), (value shr 24).toByte())
