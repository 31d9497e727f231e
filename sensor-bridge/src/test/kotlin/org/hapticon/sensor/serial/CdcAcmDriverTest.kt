package org.hapticon.sensor.serial

import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.Parity
import org.hapticon.sensor.port.StopBits
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import java.io.IOException

class CdcAcmDriverTest {
    private val transport = FakeUsbTransport()

    @Test
    fun openPort_arduinoUno_claimsBothInterfacesAndSends115200_8N1WithDtrAndRts() {
        val port = CdcAcmDriver(TestDevices.arduinoUno).openPort(transport, clock = transport.clock)

        assertEquals(listOf(0, 1), transport.claimed)
        assertEquals(
            listOf(
                ControlCall(0x21, 0x20, 0x0000, 0, ints(0x00, 0xC2, 0x01, 0x00, 0x00, 0x00, 0x08)),
                ControlCall(0x21, 0x22, 0x0003, 0),
            ),
            transport.controlCalls,
        )
        assertTrue(port.isOpen)
        assertEquals(LineSettings(), port.lineSettings)
    }

    @Test
    fun configure_9600_7E2_rtsOnly_sendsThatLineCodingAndLineState() {
        val port = CdcAcmDriver(TestDevices.arduinoUno).openPort(transport, clock = transport.clock)
        transport.controlCalls.clear()

        port.configure(LineSettings(baudRate = 9600, dataBits = 7, parity = Parity.EVEN, stopBits = StopBits.TWO, dtr = false, rts = true))

        assertEquals(
            listOf(
                ControlCall(0x21, 0x20, 0x0000, 0, ints(0x80, 0x25, 0x00, 0x00, 0x02, 0x02, 0x07)),
                ControlCall(0x21, 0x22, 0x0002, 0),
            ),
            transport.controlCalls,
        )
    }

    @Test
    fun configure_markParityOneAndAHalfStopBits_areCdcCodes3And1() {
        val port = CdcAcmDriver(TestDevices.arduinoUno).openPort(transport, clock = transport.clock)
        transport.controlCalls.clear()

        port.configure(LineSettings(baudRate = 250_000, dataBits = 5, parity = Parity.MARK, stopBits = StopBits.ONE_POINT_FIVE, dtr = false, rts = false))

        assertEquals(
            listOf(
                ControlCall(0x21, 0x20, 0x0000, 0, ints(0x90, 0xD0, 0x03, 0x00, 0x01, 0x03, 0x05)),
                ControlCall(0x21, 0x22, 0x0000, 0),
            ),
            transport.controlCalls,
        )
    }

    @Test
    fun openPort_compositeWithHidAndVendorInterfaces_usesTheAcmPairAndAddressesItsControlInterface() {
        val port = CdcAcmDriver(TestDevices.compositeCdc).openPort(transport, clock = transport.clock)
        transport.incoming += Incoming.Data(bytes(0x41))
        port.read(ByteArray(8), timeoutMillis = 10)
        port.write(bytes(0x42), timeoutMillis = 10)

        assertEquals(listOf(1, 2), transport.claimed)
        assertEquals(listOf(1, 1), transport.controlCalls.map { it.index })
        assertEquals(listOf(BulkCall(0x84, 64, 10)), transport.bulkInCalls)
        assertEquals(listOf(BulkCall(0x03, 1, 10)), transport.bulkOutCalls)
    }

    @Test
    fun portCount_dualCdc_isTwoAndTheSecondPortUsesInterfaces2And3() {
        val driver = CdcAcmDriver(TestDevices.dualCdc)

        val port = driver.openPort(transport, portIndex = 1, clock = transport.clock)
        port.write(bytes(1), timeoutMillis = 10)

        assertEquals(2, driver.portCount)
        assertEquals(listOf(2, 3), transport.claimed)
        assertEquals(listOf(2, 2), transport.controlCalls.map { it.index })
        assertEquals(0x04, transport.bulkOutCalls.single().endpoint)
    }

    @Test
    fun portCount_singleInterfaceWithBothBulkEndpoints_isOneAndClaimsItOnce() {
        val device = UsbDeviceDescription(
            0x1234, 0x0001,
            listOf(UsbInterfaceDescription(0, 0x02, 0x02, 0x01, listOf(TestDevices.interrupt(0x83), TestDevices.bulk(0x02), TestDevices.bulk(0x81)))),
        )

        CdcAcmDriver(device).openPort(transport, clock = transport.clock)

        assertEquals(listOf(0), transport.claimed)
        assertEquals(listOf(0, 0), transport.controlCalls.map { it.index })
    }

    @Test
    fun openPort_portIndexOutOfRange_throwsIllegalArgument() {
        try {
            CdcAcmDriver(TestDevices.arduinoUno).openPort(transport, portIndex = 1)
            fail("opened port 1 of a one-port device")
        } catch (e: IllegalArgumentException) {
            assertEquals("CDC-ACM device 2341:0043 has 1 port(s), no port 1", e.message)
        }
    }

    @Test
    fun openPort_dataInterfaceCannotBeClaimed_throwsAndReleasesTheControlInterface() {
        transport.refuseClaimOf = 1

        try {
            CdcAcmDriver(TestDevices.arduinoUno).openPort(transport)
            fail("opened without the data interface")
        } catch (e: IOException) {
            assertEquals("Cannot claim interface 1 of 2341:0043", e.message)
        }
        assertEquals(listOf(0), transport.released)
    }

    @Test
    fun openPort_lineCodingStalls_throwsAndReleasesBothInterfaces() {
        transport.controlResults[0x20] = -1

        try {
            CdcAcmDriver(TestDevices.arduinoUno).openPort(transport)
            fail("opened although SET_LINE_CODING failed")
        } catch (e: IOException) {
            assertEquals("SET_LINE_CODING failed on 2341:0043 (result -1)", e.message)
        }
        assertEquals(listOf(1, 0), transport.released)
    }

    @Test
    fun close_releasesDataThenControlInterfaceOnce() {
        val port = CdcAcmDriver(TestDevices.arduinoUno).openPort(transport)

        port.close()
        port.close()

        assertEquals(listOf(1, 0), transport.released)
        assertFalse(port.isOpen)
    }

    @Test
    fun isCdcAcm_vendorSpecificOrHidDevice_isFalse() {
        assertFalse(CdcAcmDriver.isCdcAcm(TestDevices.ft232r))
        assertFalse(CdcAcmDriver.isCdcAcm(TestDevices.keyboard))
        assertTrue(CdcAcmDriver.isCdcAcm(TestDevices.compositeCdc))
    }
}
