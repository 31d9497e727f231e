package org.hapticon.sensor.usb

import android.app.PendingIntent
import android.content.Context
import android.hardware.usb.UsbDevice
import android.hardware.usb.UsbManager
import java.io.IOException
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.map
import kotlinx.coroutines.flow.onStart
import org.hapticon.sensor.live.SensorDevice
import org.hapticon.sensor.live.UsbAccessDeniedException
import org.hapticon.sensor.live.UsbDevices
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SerialPort

/**
 * [UsbDevices] on the phone's USB host, through [UsbDeviceMonitor] (attach and detach),
 * [UsbPermissionRequester] (the system dialog) and [UsbSensorOpener]: what the live session opens ports
 * through, so a port is opened one way (app → sensor-bridge:usb → sensor-bridge).
 *
 * The monitor starts when [devices] is first collected, so an app that never opens the Sensors screen
 * registers no receiver.
 *
 * @param askSystem shows the permission dialog; [UsbManager.requestPermission] unless a test replaces it.
 */
class AndroidUsbDevices(
    context: Context,
    private val usbManager: UsbManager = context.getSystemService(UsbManager::class.java),
    askSystem: ((UsbDevice, PendingIntent) -> Unit)? = null,
) : UsbDevices {
    private val appContext: Context = context.applicationContext ?: context
    private val monitor = UsbDeviceMonitor(appContext, usbManager)
    private val permissions = if (askSystem == null) {
        UsbPermissionRequester(appContext, usbManager)
    } else {
        UsbPermissionRequester(appContext, usbManager, askSystem)
    }
    private val opener = UsbSensorOpener(usbManager, permissions, monitor)
    private var started = false

    override val hasUsbHost: Boolean get() = hasUsbHost(appContext)

    override val devices: Flow<List<SensorDevice>> =
        monitor.devices.onStart { start() }.map { list -> list.map { it.toSensorDevice() } }

    override fun currentDevices(): List<SensorDevice> {
        start()
        return monitor.devices.value.map { it.toSensorDevice() }
    }

    override fun refresh() {
        started = true
        monitor.refresh()
    }

    override suspend fun requestPermission(device: SensorDevice): Boolean =
        permissions.awaitPermission(usbDevice(device))

    override suspend fun open(device: SensorDevice, settings: LineSettings): SerialPort = try {
        opener.open(usbDevice(device), settings)
    } catch (e: UsbPermissionDeniedException) {
        throw UsbAccessDeniedException(device)
    }

    private fun start() {
        if (started) return
        started = true
        monitor.start()
    }

    private fun usbDevice(device: SensorDevice): UsbDevice =
        monitor.devices.value.firstOrNull { it.device.deviceName == device.id }?.device
            ?: throw IOException("USB device ${device.usbIds} is no longer plugged in")
}

private fun AttachedSerialDevice.toSensorDevice() = SensorDevice(
    id = device.deviceName,
    chipFamily = driver.chipFamily,
    vendorId = device.vendorId,
    productId = device.productId,
    productName = device.productName,
)
