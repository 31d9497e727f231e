package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.Parity
import org.hapticon.sensor.port.StopBits
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test
import java.io.IOException

class Ch34xDriverTest {
    private val transport = FakeUsbTransport()

    private fun open(version: Int, settings: LineSettings = LineSettings()): UsbSerialPort {
        transport.controlInReplies[0x5F] = bytes(version, 0x00)
        return Ch34xDriver(TestDevices.ch340).openPort(transport, settings = settings)
    }

    @Test
    fun openPort_version0x31_readsVersionInitsThenDivisorLineControlAndModemLines() {
        open(version = 0x31)

        assertEquals(listOf(0), transport.claimed)
        assertEquals(
            listOf(
                ControlCall(0xC0, 0x5F, 0x0000, 0x0000, length = 2),
                ControlCall(0x40, 0xA1, 0x0000, 0x0000),
                ControlCall(0x40, 0x9A, 0x1312, 0xCC83),
                ControlCall(0x40, 0x9A, 0x2518, 0x00C3),
                ControlCall(0x40, 0xA4, 0xFF9F, 0x0000),
            ),
            transport.controlCalls,
        )
    }

    @Test
    fun openPort_version0x27_skipsLineControlAndTheSendAtOnceBit() {
        open(version = 0x27)

        assertEquals(
            listOf(
                ControlCall(0xC0, 0x5F, 0x0000, 0x0000, length = 2),
                ControlCall(0x40, 0xA1, 0x0000, 0x0000),
                ControlCall(0x40, 0x9A, 0x1312, 0xCC03),
                ControlCall(0x40, 0xA4, 0xFF9F, 0x0000),
            ),
            transport.controlCalls,
        )
    }

    @Test
    fun configure_9600_8O2_dtrOnly_encodesLcrAndInvertedModemBits() {
        val port = open(version = 0x31)
        transport.controlCalls.clear()

        port.configure(LineSettings(baudRate = 9600, parity = Parity.ODD, stopBits = StopBits.TWO, rts = false))

        assertEquals(
            listOf(
                ControlCall(0x40, 0x9A, 0x1312, 0xB282),
                ControlCall(0x40, 0x9A, 0x2518, 0x00CF),
                ControlCall(0x40, 0xA4, 0xFFDF, 0x0000),
            ),
            transport.controlCalls,
        )
    }

    @Test
    fun configure_5DataBitsSpaceParity_setsParityMarkSpaceAndEvenBits() {
        val port = open(version = 0x30)
        transport.controlCalls.clear()

        port.configure(LineSettings(dataBits = 5, parity = Parity.SPACE, dtr = false, rts = false))

        assertEquals(ControlCall(0x40, 0x9A, 0x2518, 0x00F8), transport.controlCalls[1])
        assertEquals(ControlCall(0x40, 0xA4, 0xFFFF, 0x0000), transport.controlCalls[2])
    }

    @Test
    fun configure_7E1OnAVersion0x27Chip_throwsUnsupportedAndSendsNothing() {
        val port = open(version = 0x27)
        transport.controlCalls.clear()

        try {
            port.configure(LineSettings(dataBits = 7, parity = Parity.EVEN))
            fail("accepted 7E1 on an old chip")
        } catch (e: UnsupportedSettingException) {
            assertEquals("CH34x version 0x27 supports only 8N1", e.message)
        }
        assertEquals(emptyList<ControlCall>(), transport.controlCalls)
    }

    @Test
    fun openPort_versionRequestFails_throwsAndReleasesTheInterface() {
        try {
            Ch34xDriver(TestDevices.ch340).openPort(transport)
            fail("opened without a version reply")
        } catch (e: IOException) {
            assertEquals("CH34x READ_VERSION failed on 1a86:7523 (result -1)", e.message)
        }
        assertEquals(listOf(0), transport.released)
    }

    @Test
    fun read_usesThe32ByteBulkInEndpoint() {
        val port = open(version = 0x31)
        transport.incoming += Incoming.Data(bytes(0x31, 0x32))

        val buffer = ByteArray(40)
        val count = port.read(buffer, timeoutMillis = 20)

        assertEquals(2, count)
        assertEquals("one 32-byte packet", listOf(BulkCall(0x82, 32, 20)), transport.bulkInCalls)
    }
}
