package org.hapticon.sensor.serial

/**
 * What a driver needs to know about a USB device before it talks to it: ids and the interfaces of
 * the active configuration. Built from an Android `UsbDevice` in `:sensor-bridge:usb`, by hand in
 * tests.
 *
 * @property vendorId USB vendor id (idVendor), 0..0xFFFF.
 * @property productId USB product id (idProduct), 0..0xFFFF.
 * @property interfaces every interface and alternate setting, in descriptor order.
 * @property deviceClass bDeviceClass; 0 when each interface names its own class, 0xEF for composite
 *   devices with interface association descriptors.
 * @property name a platform name for logs and matching (Android: `/dev/bus/usb/001/004`).
 * @property productName the product string, if the device has one.
 */
public data class UsbDeviceDescription(
    val vendorId: Int,
    val productId: Int,
    val interfaces: List<UsbInterfaceDescription>,
    val deviceClass: Int = 0,
    val name: String = "",
    val productName: String? = null,
) {
    /** The interfaces with [UsbInterfaceDescription.interfaceClass] equal to [usbClass]. */
    public fun interfacesOfClass(usbClass: Int): List<UsbInterfaceDescription> =
        interfaces.filter { it.interfaceClass == usbClass }

    /** `vvvv:pppp` in lower-case hex, as `lsusb` prints it. */
    public val ids: String get() = "%04x:%04x".format(vendorId, productId)
}

/**
 * One interface (one alternate setting of it) of a USB device.
 *
 * @property id bInterfaceNumber: the number used in control requests addressed to the interface.
 * @property interfaceClass bInterfaceClass (2 CDC communications, 10 CDC data, 0xFF vendor specific).
 * @property interfaceSubclass bInterfaceSubClass (2 for CDC ACM).
 * @property interfaceProtocol bInterfaceProtocol.
 * @property endpoints the endpoints of this interface, in descriptor order.
 * @property alternateSetting bAlternateSetting.
 */
public data class UsbInterfaceDescription(
    val id: Int,
    val interfaceClass: Int,
    val interfaceSubclass: Int,
    val interfaceProtocol: Int,
    val endpoints: List<UsbEndpointDescription>,
    val alternateSetting: Int = 0,
) {
    /** The first bulk endpoint in [direction], or null. */
    public fun bulkEndpoint(direction: UsbDirection): UsbEndpointDescription? =
        endpoints.firstOrNull { it.type == UsbEndpointType.BULK && it.direction == direction }

    /** Whether serial data can move here: a bulk endpoint each way. */
    internal fun hasBulkPair(): Boolean = bulkEndpoint(UsbDirection.IN) != null && bulkEndpoint(UsbDirection.OUT) != null
}

/**
 * One endpoint of an interface.
 *
 * @property address bEndpointAddress: number in bits 0..3, bit 7 set for IN (device to host).
 * @property type the transfer type.
 * @property maxPacketSize wMaxPacketSize: 64 on full-speed bulk endpoints, 512 on high-speed.
 */
public data class UsbEndpointDescription(
    val address: Int,
    val type: UsbEndpointType,
    val maxPacketSize: Int,
) {
    /** The direction, from bit 7 of [address]. */
    public val direction: UsbDirection get() = if (address and 0x80 != 0) UsbDirection.IN else UsbDirection.OUT
}

/** Direction of an endpoint, seen from the host. */
public enum class UsbDirection {
    /** Device to host (reads). */
    IN,

    /** Host to device (writes). */
    OUT,
}

/** USB transfer type of an endpoint, in the order of bmAttributes bits 0..1. */
public enum class UsbEndpointType {
    /** Type 0: the default control pipe. */
    CONTROL,

    /** Type 1: isochronous (audio, video). */
    ISOCHRONOUS,

    /** Type 2: bulk, which carries serial data. */
    BULK,

    /** Type 3: interrupt, which carries CDC notifications. */
    INTERRUPT,
    ;

    /** Lookup from bmAttributes. */
    public companion object {
        /** The type named by bits 0..1 of an endpoint's bmAttributes. */
        public fun fromAttributes(attributes: Int): UsbEndpointType = entries[attributes and 0x03]
    }
}
