package org.hapticon.sensor.serial

/**
 * Which driver serves which (vendor id, product id). Build one with [add], or start from
 * [ProbeTable.default] and add a lab's own boards.
 */
public class ProbeTable {
    private val factories = LinkedHashMap<Int, UsbSerialDriverFactory>()

    /** Serves ([vendorId], [productId]) with [factory], replacing an earlier entry. Returns this table. */
    public fun add(vendorId: Int, productId: Int, factory: UsbSerialDriverFactory): ProbeTable {
        require(vendorId in 0..0xFFFF && productId in 0..0xFFFF) { "ids must be 16-bit, were $vendorId:$productId" }
        factories[key(vendorId, productId)] = factory
        return this
    }

    /** The driver for [device] if its ids are in the table, else null. */
    public fun find(device: UsbDeviceDescription): UsbSerialDriver? =
        factories[key(device.vendorId, device.productId)]?.create(device)

    /** The vendor ids with at least one entry, for checking the Android device filter against. */
    public val vendorIds: Set<Int> get() = factories.keys.mapTo(LinkedHashSet()) { it ushr 16 }

    /** The boards and chips Hapticon knows. */
    public companion object {
        /** A new table with every chip and board in docs/usb.md. */
        public fun default(): ProbeTable = ProbeTable().apply {
            KnownUsbSerialDevices.FTDI_PRODUCTS.forEach { add(KnownUsbSerialDevices.VENDOR_FTDI, it, ::FtdiDriver) }
            KnownUsbSerialDevices.SILABS_PRODUCTS.forEach { add(KnownUsbSerialDevices.VENDOR_SILABS, it, ::Cp21xxDriver) }
            KnownUsbSerialDevices.QINHENG_UART_PRODUCTS.forEach { add(KnownUsbSerialDevices.VENDOR_QINHENG, it, ::Ch34xDriver) }
            KnownUsbSerialDevices.CDC_ACM_BOARDS.forEach { (vendor, product) -> add(vendor, product, ::CdcAcmDriver) }
        }

        private fun key(vendorId: Int, productId: Int) = (vendorId shl 16) or productId
    }
}

/** Vendor and product ids of the supported chips and boards (see docs/usb.md). */
public object KnownUsbSerialDevices {
    /** Future Technology Devices International. */
    public const val VENDOR_FTDI: Int = 0x0403

    /** Silicon Labs. */
    public const val VENDOR_SILABS: Int = 0x10C4

    /** Nanjing QinHeng (WCH). */
    public const val VENDOR_QINHENG: Int = 0x1A86

    /** Arduino SA. */
    public const val VENDOR_ARDUINO: Int = 0x2341

    /** Van Ooijen Technische Informatica, whose ids PJRC's Teensy uses. */
    public const val VENDOR_PJRC: Int = 0x16C0

    /** Espressif. */
    public const val VENDOR_ESPRESSIF: Int = 0x303A

    /** Raspberry Pi. */
    public const val VENDOR_RASPBERRY_PI: Int = 0x2E8A

    /** FT232R/FT245R, FT2232C/D/H, FT4232H, FT232H, FT-X (FT231X, FT230X). */
    public val FTDI_PRODUCTS: List<Int> = listOf(0x6001, 0x6010, 0x6011, 0x6014, 0x6015)

    /** CP2102/CP2102N/CP2104, CP2105 (2 ports), CP2108 (4 ports). CP2110 (0xEA80) is a HID device, not CP210x. */
    public val SILABS_PRODUCTS: List<Int> = listOf(0xEA60, 0xEA70, 0xEA71)

    /** CH340, CH340K, CH341A in UART mode. The CH9102/CH343 (0x55D4, 0x55D3) are CDC ACM and found by class. */
    public val QINHENG_UART_PRODUCTS: List<Int> = listOf(0x7523, 0x7522, 0x5523)

    /**
     * Native-USB boards that speak CDC ACM, as (vendor, product): Arduino Uno, Mega 2560, Mega R3, Uno R3,
     * Leonardo, Micro; Teensy serial; ESP32-S3/C3 USB-Serial-JTAG; Raspberry Pi Pico SDK and
     * MicroPython. Other CDC boards are found by class.
     */
    public val CDC_ACM_BOARDS: List<Pair<Int, Int>> = listOf(
        VENDOR_ARDUINO to 0x0001,
        VENDOR_ARDUINO to 0x0010,
        VENDOR_ARDUINO to 0x0042,
        VENDOR_ARDUINO to 0x0043,
        VENDOR_ARDUINO to 0x8036,
        VENDOR_ARDUINO to 0x8037,
        VENDOR_PJRC to 0x0483,
        VENDOR_ESPRESSIF to 0x1001,
        VENDOR_RASPBERRY_PI to 0x000A,
        VENDOR_RASPBERRY_PI to 0x0005,
    )
}
