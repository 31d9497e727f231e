package org.hapticon.sensor.usb

import android.content.Context
import android.hardware.usb.UsbManager
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.runBlocking
import org.hapticon.sensor.live.SensorDevice
import org.hapticon.sensor.port.LineSettings
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.hapticon.testing.android.AndroidTestDevices
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import java.io.IOException

/** The session's USB device list on Android: what it lists and how opening fails. */
@RunWith(RobolectricTestRunner::class)
class AndroidUsbDevicesTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val usbManager = context.getSystemService(UsbManager::class.java)
    private val asked = mutableListOf<String>()
    private val devices = AndroidUsbDevices(context, usbManager) { device, _ -> asked += device.deviceName }

    @Test
    fun currentDevices_pluggedInBoardsAndAKeyboard_listsTheBoardsAsSensorDevices() {
        shadowOf(usbManager).addOrUpdateUsbDevice(AndroidTestDevices.arduinoUno(), false)
        shadowOf(usbManager).addOrUpdateUsbDevice(AndroidTestDevices.keyboard(), false)

        val listed = devices.currentDevices()

        assertEquals(listOf(SensorDevice("/dev/bus/usb/001/002", "CDC-ACM", 0x2341, 0x0043, listed.single().productName)), listed)
        assertEquals("2341:0043", listed.single().usbIds)
    }

    @Test
    fun open_deviceNoLongerPluggedIn_failsWithItsIds() {
        val gone = SensorDevice("/dev/bus/usb/001/009", "FTDI", 0x0403, 0x6001, null)

        val e = assertThrows(IOException::class.java) { runBlocking { devices.open(gone, LineSettings(baudRate = 115_200)) } }

        assertEquals("USB device 0403:6001 is no longer plugged in", e.message)
    }

    @Test
    fun requestPermission_alreadyGranted_isTrueWithoutTheDialog() {
        shadowOf(usbManager).addOrUpdateUsbDevice(AndroidTestDevices.arduinoUno(), true)
        val uno = devices.currentDevices().single()

        assertTrue(runBlocking { devices.requestPermission(uno) })
        assertTrue(asked.isEmpty())
    }
}
