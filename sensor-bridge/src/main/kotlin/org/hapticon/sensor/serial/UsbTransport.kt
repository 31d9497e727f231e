package org.hapticon.sensor.serial

/**
 * The USB operations the serial drivers need, shaped like Android's `UsbDeviceConnection` so the
 * Android adapter is a thin pass-through and tests can record every transfer.
 *
 * Return values follow Android: the number of bytes transferred, or a negative number on error
 * *and on timeout* (Android does not tell the two apart, which is why [isDeviceAttached] exists).
 */
public interface UsbTransport {
    /**
     * Claims [usbInterface] for exclusive use, detaching a kernel driver if one is bound.
     * @return false if the interface could not be claimed.
     */
    public fun claimInterface(usbInterface: UsbInterfaceDescription): Boolean

    /** Releases an interface claimed with [claimInterface]; false if that failed. */
    public fun releaseInterface(usbInterface: UsbInterfaceDescription): Boolean

    /**
     * A control transfer on endpoint 0. [requestType] bit 7 gives the direction: IN transfers fill
     * [data], OUT transfers send its first [length] bytes ([data] may be null when [length] is 0).
     * @return bytes transferred, or negative on error or timeout.
     */
    public fun controlTransfer(
        requestType: Int,
        request: Int,
        value: Int,
        index: Int,
        data: ByteArray?,
        length: Int,
        timeoutMillis: Int,
    ): Int

    /**
     * A bulk transfer on [endpoint], reading into or writing from [buffer] at [offset].
     * [timeoutMillis] 0 waits for ever.
     * @return bytes transferred, or negative on error or timeout.
     */
    public fun bulkTransfer(endpoint: UsbEndpointDescription, buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int

    /**
     * Whether the device still answers: false once it was unplugged. Asked after a failed transfer
     * to tell a timeout (device present, nothing to read) from an unplug. Implementations send a
     * standard GET_STATUS request or remember a detach broadcast.
     */
    public fun isDeviceAttached(): Boolean

    /** The raw device and configuration descriptors, or null if the platform cannot give them. */
    public fun rawDescriptors(): ByteArray?
}
