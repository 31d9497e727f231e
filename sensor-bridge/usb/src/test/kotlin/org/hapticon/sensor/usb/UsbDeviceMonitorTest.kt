package org.hapticon.sensor.usb

import android.content.Context
import android.content.Intent
import android.hardware.usb.UsbDevice
import android.hardware.usb.UsbManager
import android.os.Looper
import androidx.test.core.app.ApplicationProvider
import org.hapticon.testing.android.AndroidTestDevices
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

@RunWith(RobolectricTestRunner::class)
class UsbDeviceMonitorTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val usbManager = context.getSystemService(UsbManager::class.java)
    private val monitor = UsbDeviceMonitor(context, usbManager)

    @After
    fun stop() = monitor.close()

    private fun broadcast(action: String, device: UsbDevice) {
        context.sendBroadcast(Intent(action).putExtra(UsbManager.EXTRA_DEVICE, device))
        shadowOf(Looper.getMainLooper()).idle()
    }

    private fun plugIn(device: UsbDevice) {
        shadowOf(usbManager).addOrUpdateUsbDevice(device, false)
        broadcast(UsbManager.ACTION_USB_DEVICE_ATTACHED, device)
    }

    private fun unplug(device: UsbDevice) {
        shadowOf(usbManager).removeUsbDevice(device)
        broadcast(UsbManager.ACTION_USB_DEVICE_DETACHED, device)
    }

    private fun listed(): List<Pair<String, String>> = monitor.devices.value.map { it.device.deviceName to it.driver.chipFamily }

    @Test
    fun start_devicesAlreadyPluggedIn_listsOnlyTheSerialOnes() {
        shadowOf(usbManager).addOrUpdateUsbDevice(AndroidTestDevices.arduinoUno(), false)
        shadowOf(usbManager).addOrUpdateUsbDevice(AndroidTestDevices.keyboard(), false)

        monitor.start()

        assertEquals(listOf("/dev/bus/usb/001/002" to "CDC-ACM"), listed())
    }

    @Test
    fun refresh_findsABoardThatCameWithoutABroadcast_andStartsTheMonitor() {
        monitor.start()
        // Some hubs announce a board late: it is in the system's list, but no broadcast said so.
        shadowOf(usbManager).addOrUpdateUsbDevice(AndroidTestDevices.arduinoUno(), false)
        assertEquals(emptyList<Pair<String, String>>(), listed())

        monitor.refresh()

        assertEquals(listOf("/dev/bus/usb/001/002" to "CDC-ACM"), listed())
        val fresh = UsbDeviceMonitor(context, usbManager)
        fresh.refresh()
        assertEquals(1, fresh.devices.value.size)
        fresh.close()
    }

    @Test
    fun attachThenDetach_updatesTheList() {
        monitor.start()
        val ftdi = AndroidTestDevices.ft232r()

        plugIn(ftdi)
        val afterAttach = listed()
        unplug(ftdi)

        assertEquals(listOf("/dev/bus/usb/001/003" to "FTDI"), afterAttach)
        assertEquals(emptyList<Pair<String, String>>(), listed())
    }

    @Test
    fun detach_deviceStillInTheSystemList_isLeftOutAnyway() {
        monitor.start()
        val uno = AndroidTestDevices.arduinoUno()
        plugIn(uno)

        broadcast(UsbManager.ACTION_USB_DEVICE_DETACHED, uno)

        assertEquals(emptyList<Pair<String, String>>(), listed())
    }

    @Test
    fun detach_notifiesListenersUntilTheirHandleIsClosed() {
        monitor.start()
        val uno = AndroidTestDevices.arduinoUno()
        val detached = mutableListOf<String>()
        val registration = monitor.addDetachListener { detached += it.deviceName }

        plugIn(uno)
        unplug(uno)
        registration.close()
        plugIn(uno)
        unplug(uno)

        assertEquals(listOf("/dev/bus/usb/001/002"), detached)
    }

    @Test
    fun close_stopsFollowingBroadcasts() {
        monitor.start()
        monitor.close()

        plugIn(AndroidTestDevices.arduinoUno())

        assertEquals(emptyList<Pair<String, String>>(), listed())
    }
}
