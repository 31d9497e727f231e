package org.hapticon.sensor.live

import java.io.IOException
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SerialPort

/** An Arduino Uno as [SensorDevice]. */
val TEST_UNO = SensorDevice("/dev/bus/usb/001/002", "CDC-ACM", 0x2341, 0x0043, "Uno")

/** [UsbDevices] that lists [devices] and opens the ports a test put in [ports]. */
class TestUsbDevices(devices: List<SensorDevice> = listOf(TEST_UNO), override val hasUsbHost: Boolean = true) : UsbDevices {
    val deviceList = MutableStateFlow(devices)
    val ports = mutableMapOf<String, SerialPort>()
    var grantPermission = true
    val opened = mutableListOf<Pair<SensorDevice, LineSettings>>()

    override val devices: Flow<List<SensorDevice>> = deviceList
    override fun currentDevices(): List<SensorDevice> = deviceList.value
    override fun refresh() = Unit

    override suspend fun requestPermission(device: SensorDevice): Boolean = grantPermission

    override suspend fun open(device: SensorDevice, settings: LineSettings): SerialPort {
        opened += device to settings
        return ports[device.id] ?: throw IOException("no such test port")
    }
}
