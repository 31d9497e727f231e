package org.hapticon.sensor.usb

import android.content.Context
import android.hardware.usb.UsbDevice
import android.hardware.usb.UsbManager
import kotlinx.coroutines.CoroutineDispatcher
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.PortDisconnectedException
import org.hapticon.sensor.serial.UsbSerialProber
import java.io.IOException

/** The user refused access to a USB device in the system dialog. */
class UsbPermissionDeniedException(device: UsbDevice) :
    IOException("Access to USB device ${device.deviceName} (${device.usbIds}) was denied")

/**
 * Goes from a plugged-in device to an open [UsbSensorConnection]: probe a driver, ask permission,
 * open the USB connection, open and configure the driver's port, and watch for the unplug.
 *
 * @param ioDispatcher where the blocking USB requests of opening run.
 */
class UsbSensorOpener(
    private val usbManager: UsbManager,
    private val permissions: UsbPermissionRequester,
    private val monitor: UsbDeviceMonitor,
    private val prober: UsbSerialProber = UsbSerialProber(),
    private val ioDispatcher: CoroutineDispatcher = Dispatchers.IO,
) {
    /** An opener with the system's USB manager, a permission requester and [monitor]. */
    constructor(context: Context, monitor: UsbDeviceMonitor) :
        this(context.getSystemService(UsbManager::class.java), UsbPermissionRequester(context), monitor)

    /**
     * Opens port [portIndex] of [device] with [settings] (DTR and RTS asserted by default). Call from
     * the main thread or a coroutine that may wait for the permission dialog.
     *
     * @throws UsbPermissionDeniedException if the user refused.
     * @throws PortDisconnectedException if the device went away while opening.
     * @throws org.hapticon.sensor.serial.UnsupportedSettingException if the chip cannot do [settings].
     * @throws IOException if the device is not a supported serial device or the USB requests fail.
     */
    suspend fun open(device: UsbDevice, settings: LineSettings = LineSettings(), portIndex: Int = 0): UsbSensorConnection {
        val driver = prober.probe(device.toDescription())
            ?: throw IOException("USB device ${device.deviceName} (${device.usbIds}) is not a supported serial device")
        monitor.start()
        if (!permissions.awaitPermission(device)) throw UsbPermissionDeniedException(device)
        val connection = withContext(ioDispatcher) {
            val usbConnection = usbManager.openDevice(device) ?: throw PortDisconnectedException("USB device ${device.deviceName} could not be opened")
            val transport = AndroidUsbTransport(device, usbConnection)
            val port = try {
                driver.openPort(transport, portIndex, settings)
            } catch (e: Exception) {
                transport.close()
                throw e
            }
            UsbSensorConnection(device, driver, port, transport)
        }
        connection.watchDetach(monitor)
        // Unplugged between opening and watching: the broadcast is gone, so look at the device list.
        if (usbManager.deviceList.values.none { it.deviceName == device.deviceName }) {
            connection.onDetached()
            throw PortDisconnectedException("USB device ${device.deviceName} was unplugged while opening")
        }
        return connection
    }
}
