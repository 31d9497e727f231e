package org.hapticon.testing

import java.io.IOException
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import org.hapticon.sensor.live.SensorDevice
import org.hapticon.sensor.live.UsbDevices
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SerialPort

/** An Arduino Uno as [SensorDevice]. */
val TEST_UNO = SensorDevice("/dev/bus/usb/001/002", "CDC-ACM", 0x2341, 0x0043, "Uno")

/**
 * [UsbDevices] that lists [devices] and opens the ports a test put in [ports]; it records what was [opened] and
 * how many [refreshes] were asked for. The one double for sensor-bridge's live-session tests and the app's screens.
 */
class TestUsbDevices(devices: List<SensorDevice> = listOf(TEST_UNO), override val hasUsbHost: Boolean = true) : UsbDevices {
    val deviceList = MutableStateFlow(devices)
    val ports = mutableMapOf<String, SerialPort>()
    var grantPermission = true
    val opened = mutableListOf<Pair<SensorDevice, LineSettings>>()
    var refreshes = 0

    override val devices: Flow<List<SensorDevice>> = deviceList
    override fun currentDevices(): List<SensorDevice> = deviceList.value
    override fun refresh() {
        refreshes++
    }

    override suspend fun requestPermission(device: SensorDevice): Boolean = grantPermission

    override suspend fun open(device: SensorDevice, settings: LineSettings): SerialPort {
        opened += device to settings
        return ports[device.id] ?: throw IOException("no such test port")
    }
}
