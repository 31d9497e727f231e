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
import kotlinx.coroutines.test.runCurrent
import kotlinx.coroutines.test.runTest
import org.hapticon.testing.android.AndroidTestDevices
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

@RunWith(RobolectricTestRunner::class)
class UsbPermissionRequesterTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val usbManager = context.getSystemService(UsbManager::class.java)
    private val device = AndroidTestDevices.arduinoUno()
    private val asked = mutableListOf<Pair<UsbDevice, PendingIntent>>()
    private val requester = UsbPermissionRequester(context, usbManager) { d, intent -> asked += d to intent }
    private val results = mutableListOf<Boolean>()

    /** What the system does when the user answers: fill in the device and the answer, send the intent. */
    private fun answer(granted: Boolean, forDevice: UsbDevice = device) {
        val fillIn = Intent().putExtra(UsbManager.EXTRA_DEVICE, forDevice).putExtra(UsbManager.EXTRA_PERMISSION_GRANTED, granted)
        asked.last().second.send(context, 0, fillIn)
        shadowOf(Looper.getMainLooper()).idle()
    }

    @Test
    fun request_userGrants_reportsTrueOnce() {
        shadowOf(usbManager).addOrUpdateUsbDevice(device, false)

        requester.request(device) { results += it }
        answer(granted = true)
        answer(granted = true)

        assertEquals(listOf(true), results)
    }

    @Test
    fun request_userDenies_reportsFalse() {
        shadowOf(usbManager).addOrUpdateUsbDevice(device, false)

        requester.request(device) { results += it }
        answer(granted = false)

        assertEquals(listOf(false), results)
    }

    @Test
    fun request_alreadyGranted_reportsTrueAtOnceWithoutTheDialog() {
        shadowOf(usbManager).addOrUpdateUsbDevice(device, true)

        requester.request(device) { results += it }

        assertEquals(listOf(true), results)
        assertTrue(asked.isEmpty())
    }

    @Test
    fun request_answerForAnotherDevice_isIgnored() {
        shadowOf(usbManager).addOrUpdateUsbDevice(device, false)
        val other = AndroidTestDevices.ft232r()

        requester.request(device) { results += it }
        answer(granted = true, forDevice = other)

        assertEquals(emptyList<Boolean>(), results)
    }

    @Test
    fun request_closedBeforeTheAnswer_neverReports() {
        shadowOf(usbManager).addOrUpdateUsbDevice(device, false)

        requester.request(device) { results += it }.close()
        answer(granted = true)

        assertEquals(emptyList<Boolean>(), results)
    }

    @Test
    fun request_pendingIntent_isAnExplicitMutableBroadcast() {
        shadowOf(usbManager).addOrUpdateUsbDevice(device, false)

        requester.request(device) { results += it }

        val pendingIntent = shadowOf(asked.single().second)
        assertTrue(pendingIntent.isBroadcast)
        assertFalse(pendingIntent.isImmutable)
        assertEquals(PendingIntent.FLAG_MUTABLE, pendingIntent.flags and PendingIntent.FLAG_MUTABLE)
        assertEquals(context.packageName, pendingIntent.savedIntent.`package`)
        assertEquals(UsbPermissionRequester.ACTION_USB_PERMISSION, pendingIntent.savedIntent.action)
        assertEquals(device, asked.single().first)
    }

    @OptIn(ExperimentalCoroutinesApi::class)
    @Test
    fun awaitPermission_userGrants_resumesWithTrue() = runTest {
        shadowOf(usbManager).addOrUpdateUsbDevice(device, false)

        val granted = async { requester.awaitPermission(device) }
        runCurrent()
        answer(granted = true)

        assertTrue(granted.await())
    }
}
