package org.hapticon.sensor.serial

/** Descriptions of real devices, as Android reports them. */
object TestDevices {
    fun bulk(address: Int, maxPacketSize: Int = 64) = UsbEndpointDescription(address, UsbEndpointType.BULK, maxPacketSize)

    fun interrupt(address: Int, maxPacketSize: Int = 8) = UsbEndpointDescription(address, UsbEndpointType.INTERRUPT, maxPacketSize)

    fun cdcControl(id: Int, notify: Int) = UsbInterfaceDescription(id, 0x02, 0x02, 0x01, listOf(interrupt(notify)))

    fun cdcData(id: Int, out: Int, `in`: Int) = UsbInterfaceDescription(id, 0x0A, 0x00, 0x00, listOf(bulk(out), bulk(`in`)))

    fun vendor(id: Int, vararg endpoints: UsbEndpointDescription) = UsbInterfaceDescription(id, 0xFF, 0xFF, 0xFF, endpoints.toList())

    /** Arduino Uno R3: the 16U2 is a plain two-interface CDC ACM device; data OUT 0x04, IN 0x83. */
    val arduinoUno = UsbDeviceDescription(0x2341, 0x0043, listOf(cdcControl(0, 0x82), cdcData(1, 0x04, 0x83)), deviceClass = 0x02)

    /**
     * A TinyUSB composite board (RP2040 or ESP32-S3 firmware): HID at 0, the CDC pair at 1 and 2 (out
     * 0x03, in 0x84), a vendor interface with its own bulk endpoints at 3. Device class 0xEF (IAD).
     */
    val compositeCdc = UsbDeviceDescription(
        0x239A, 0x80F4,
        listOf(
            UsbInterfaceDescription(0, 0x03, 0x00, 0x00, listOf(interrupt(0x81))),
            cdcControl(1, 0x82),
            cdcData(2, 0x03, 0x84),
            vendor(3, bulk(0x05), bulk(0x86)),
        ),
        deviceClass = 0xEF,
    )

    /** TinyUSB dual CDC: two ACM functions, 0/1 and 2/3. */
    val dualCdc = UsbDeviceDescription(
        0xCAFE, 0x4002,
        listOf(cdcControl(0, 0x81), cdcData(1, 0x02, 0x82), cdcControl(2, 0x83), cdcData(3, 0x04, 0x84)),
        deviceClass = 0xEF,
    )

    /** WCH CH9102: vendor id of the CH340 but plain CDC ACM; not in the table, found by class. */
    val ch9102 = UsbDeviceDescription(0x1A86, 0x55D4, listOf(cdcControl(0, 0x83), cdcData(1, 0x02, 0x82)), deviceClass = 0x02)

    val ft232r = UsbDeviceDescription(0x0403, 0x6001, listOf(vendor(0, bulk(0x81), bulk(0x02))))

    val ft232h = UsbDeviceDescription(0x0403, 0x6014, listOf(vendor(0, bulk(0x81, 512), bulk(0x02, 512))))

    val ft2232h = UsbDeviceDescription(
        0x0403, 0x6010,
        listOf(vendor(0, bulk(0x81, 512), bulk(0x02, 512)), vendor(1, bulk(0x83, 512), bulk(0x04, 512))),
    )

    val cp2102 = UsbDeviceDescription(0x10C4, 0xEA60, listOf(vendor(0, bulk(0x81), bulk(0x01))))

    val cp2105 = UsbDeviceDescription(0x10C4, 0xEA70, listOf(vendor(0, bulk(0x81), bulk(0x01)), vendor(1, bulk(0x82), bulk(0x02))))

    /** CH340G: interrupt IN 0x81, bulk OUT 0x02 and IN 0x82, 32-byte packets. */
    val ch340 = UsbDeviceDescription(0x1A86, 0x7523, listOf(vendor(0, interrupt(0x81), bulk(0x02, 32), bulk(0x82, 32))))

    /** A HID-only device (a keyboard): not serial. */
    val keyboard = UsbDeviceDescription(0x046D, 0xC31C, listOf(UsbInterfaceDescription(0, 0x03, 0x01, 0x01, listOf(interrupt(0x81)))))

    /** An 18-byte device descriptor with [bcdDevice], as getRawDescriptors() starts. */
    fun deviceDescriptor(vendorId: Int, productId: Int, bcdDevice: Int): ByteArray = bytes(
        18, 0x01, 0x00, 0x02, 0x00, 0x00, 0x00, 64,
        vendorId and 0xFF, vendorId shr 8, productId and 0xFF, productId shr 8,
        bcdDevice and 0xFF, bcdDevice shr 8, 1, 2, 3, 1,
    )
}
