package org.hapticon.sensor.usb

import android.content.Context
import android.hardware.usb.UsbManager
import androidx.test.core.app.ApplicationProvider
import org.hapticon.sensor.serial.UsbEndpointDescription
import org.hapticon.sensor.serial.UsbEndpointType
import org.hapticon.testing.android.AndroidTestDevices
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

@RunWith(RobolectricTestRunner::class)
class AndroidUsbTransportTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val usbManager = context.getSystemService(UsbManager::class.java)
    private val device = AndroidTestDevices.arduinoUno()

    private fun openTransport(): AndroidUsbTransport {
        shadowOf(usbManager).addOrUpdateUsbDevice(device, true)
        return AndroidUsbTransport(device, usbManager.openDevice(device))
    }

    @Test
    fun isDeviceAttached_getStatusAnswered_isTrueUntilMarkedDetached() {
        val transport = openTransport()

        assertTrue(transport.isDeviceAttached())
        transport.markDetached()
        assertFalse(transport.isDeviceAttached())
    }

    @Test
    fun claimInterface_describedInterface_claimsTheMatchingUsbInterface() {
        val transport = openTransport()

        assertTrue(transport.claimInterface(device.toDescription().interfaces[1]))
    }

    @Test
    fun bulkTransfer_endpointTheDeviceDoesNotHave_throwsIllegalArgument() {
        val transport = openTransport()

        try {
            transport.bulkTransfer(UsbEndpointDescription(0x05, UsbEndpointType.BULK, 64), ByteArray(4), 0, 4, 10)
            fail("used a missing endpoint")
        } catch (e: IllegalArgumentException) {
            assertEquals("No endpoint 0x05 on this device", e.message)
        }
    }
}
