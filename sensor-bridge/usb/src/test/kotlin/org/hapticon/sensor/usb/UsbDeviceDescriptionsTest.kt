package org.hapticon.sensor.usb

import org.hapticon.sensor.serial.UsbDeviceDescription
import org.hapticon.sensor.serial.UsbEndpointDescription
import org.hapticon.sensor.serial.UsbEndpointType
import org.hapticon.sensor.serial.UsbInterfaceDescription
import org.hapticon.testing.android.AndroidTestDevices
import org.junit.Assert.assertEquals
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

@RunWith(RobolectricTestRunner::class)
class UsbDeviceDescriptionsTest {
    @Test
    fun toDescription_arduinoUno_carriesIdsClassesAndEndpoints() {
        val description = AndroidTestDevices.arduinoUno().toDescription()

        assertEquals(
            UsbDeviceDescription(
                vendorId = 0x2341,
                productId = 0x0043,
                interfaces = listOf(
                    UsbInterfaceDescription(0, 0x02, 0x02, 0x01, listOf(UsbEndpointDescription(0x82, UsbEndpointType.INTERRUPT, 8))),
                    UsbInterfaceDescription(
                        1, 0x0A, 0x00, 0x00,
                        listOf(UsbEndpointDescription(0x04, UsbEndpointType.BULK, 64), UsbEndpointDescription(0x83, UsbEndpointType.BULK, 64)),
                    ),
                ),
                deviceClass = 0x02,
                name = "/dev/bus/usb/001/002",
                productName = "Board",
            ),
            description,
        )
    }
}
