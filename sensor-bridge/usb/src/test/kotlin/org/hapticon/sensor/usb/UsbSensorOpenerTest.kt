package org.hapticon.sensor.usb

import android.app.PendingIntent
import android.content.Context
import android.content.Intent
import android.hardware.usb.UsbDevice
import android.hardware.usb.UsbManager
import android.os.Looper
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.async
import kotlinx.coroutines.test.UnconfinedTestDispatcher
import kotlinx.coroutines.test.runCurrent
import kotlinx.coroutines.test.runTest
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.PortDisconnectedException
import org.hapticon.testing.android.AndroidTestDevices
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import java.io.IOException

@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class UsbSensorOpenerTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val usbManager = context.getSystemService(UsbManager::class.java)
    private val monitor = UsbDeviceMonitor(context, usbManager)
    private val asked = mutableListOf<PendingIntent>()
    private val permissions = UsbPermissionRequester(context, usbManager) { _, intent -> asked += intent }
    private val uno = AndroidTestDevices.arduinoUno()

    @After
    fun stop() = monitor.close()

    private fun opener(scheduler: kotlinx.coroutines.test.TestCoroutineScheduler) =
        UsbSensorOpener(usbManager, permissions, monitor, ioDispatcher = UnconfinedTestDispatcher(scheduler))

    private fun broadcastDetach(device: UsbDevice) {
        shadowOf(usbManager).removeUsbDevice(device)
        context.sendBroadcast(Intent(UsbManager.ACTION_USB_DEVICE_DETACHED).putExtra(UsbManager.EXTRA_DEVICE, device))
        shadowOf(Looper.getMainLooper()).idle()
    }

    @Test
    fun open_permittedCdcDevice_givesAnOpenPortWithTheRequestedSettings() = runTest {
        shadowOf(usbManager).addOrUpdateUsbDevice(uno, true)

        val connection = opener(testScheduler).open(uno, LineSettings(baudRate = 9600))

        assertTrue(connection.isOpen)
        assertEquals("CDC-ACM", connection.driver.chipFamily)
        assertTrue(asked.isEmpty())
        connection.close()
        assertFalse(connection.isOpen)
    }

    @Test
    fun open_thenUnplugged_closesItselfAndReadsThrowDisconnected() = runTest {
        shadowOf(usbManager).addOrUpdateUsbDevice(uno, true)
        val connection = opener(testScheduler).open(uno)

        broadcastDetach(uno)

        assertFalse(connection.isOpen)
        try {
            connection.read(ByteArray(8), timeoutMillis = 10)
            fail("read from an unplugged device")
        } catch (e: PortDisconnectedException) {
            assertEquals("USB device 2341:0043 was unplugged", e.message)
        }
    }

    @Test
    fun open_userDenies_throwsPermissionDenied() = runTest {
        shadowOf(usbManager).addOrUpdateUsbDevice(uno, false)

        val opening = async { runCatching { opener(testScheduler).open(uno) } }
        runCurrent()
        asked.single().send(context, 0, Intent().putExtra(UsbManager.EXTRA_DEVICE, uno).putExtra(UsbManager.EXTRA_PERMISSION_GRANTED, false))
        shadowOf(Looper.getMainLooper()).idle()

        val error = opening.await().exceptionOrNull()
        assertTrue("was $error", error is UsbPermissionDeniedException)
        assertEquals("Access to USB device /dev/bus/usb/001/002 (2341:0043) was denied", error?.message)
    }

    @Test
    fun open_deviceThatIsNotSerial_throwsWithoutAskingPermission() = runTest {
        val keyboard = AndroidTestDevices.keyboard()
        shadowOf(usbManager).addOrUpdateUsbDevice(keyboard, false)

        try {
            opener(testScheduler).open(keyboard)
            fail("opened a keyboard")
        } catch (e: IOException) {
            assertEquals("USB device /dev/bus/usb/001/004 (046d:c31c) is not a supported serial device", e.message)
        }
        assertTrue(asked.isEmpty())
    }
}
