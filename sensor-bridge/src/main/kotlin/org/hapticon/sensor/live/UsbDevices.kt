package org.hapticon.sensor.live

import java.io.IOException
import kotlinx.coroutines.flow.Flow
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SerialPort

/** A plugged-in USB serial board, as the UI lists it. */
public data class SensorDevice(
    /** Stable while plugged in: the platform's device name, e.g. `/dev/bus/usb/001/002`. */
    val id: String,
    /** The driver's chip family: `CDC-ACM`, `FTDI`, `CP210x`, `CH34x`. */
    val chipFamily: String,
    val vendorId: Int,
    val productId: Int,
    /** The product string, if the board has one. */
    val productName: String? = null,
) {
    /** `vvvv:pppp` in lower-case hex, as `lsusb` prints it. */
    public val usbIds: String get() = "%04x:%04x".format(vendorId, productId)
}

/** The user refused access to [device] in the system's USB dialog. */
public class UsbAccessDeniedException(public val device: SensorDevice) : IOException("Access to ${device.usbIds} was denied")

/**
 * The phone's USB serial boards: which are plugged in, permission, and opening one. The Android
 * implementation is `AndroidUsbDevices` in :sensor-bridge:usb; tests use a double that
 * hands out fake ports. [SensorSession] opens its boards through this.
 */
public interface UsbDevices {
    /** Whether this phone can host USB devices at all (USB OTG). Without it nothing can be listed. */
    public val hasUsbHost: Boolean

    /** The serial boards plugged in now; emits again on every attach and detach. */
    public val devices: Flow<List<SensorDevice>>

    /** The boards plugged in right now. */
    public fun currentDevices(): List<SensorDevice>

    /** Lists the boards again (after a `USB_DEVICE_ATTACHED` intent reached the activity). */
    public fun refresh()

    /**
     * Asks for access to [device] (the system dialog) unless already granted; true if granted.
     * Suspends while the dialog is up; cancelling abandons the request.
     */
    public suspend fun requestPermission(device: SensorDevice): Boolean

    /**
     * Opens [device]'s first serial port with [settings]. The port reports an unplug as
     * [org.hapticon.sensor.port.PortDisconnectedException] from then on.
     * @throws UsbAccessDeniedException if access was refused.
     * @throws IOException if the board is gone, unsupported, or cannot do [settings].
     */
    public suspend fun open(device: SensorDevice, settings: LineSettings): SerialPort
}
