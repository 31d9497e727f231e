package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.Parity
import org.hapticon.sensor.port.StopBits
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test

class FtdiDriverTest {
    private val transport = FakeUsbTransport().apply { descriptors = TestDevices.deviceDescriptor(0x0403, 0x6001, 0x0600) }

    private fun openFt232r() = FtdiDriver(TestDevices.ft232r).openPort(transport, clock = transport.clock)

    /** A 64-byte packet: 2 status bytes (0x01 0x60, modem idle) then 62 payload bytes from [start]. */
    private fun packet(start: Int, payload: Int = 62) = bytes(0x01, 0x60) + ramp(payload, start)

    @Test
    fun openPort_ft232r_resetsSetsLatencyThen115200_8N1AndRaisesDtrRts() {
        openFt232r()

        assertEquals(listOf(0), transport.claimed)
        assertEquals(
            listOf(
                ControlCall(0x40, 0x00, 0x0000, 1),
                ControlCall(0x40, 0x09, 0x0001, 1),
                ControlCall(0x40, 0x03, 0x001A, 0x0000),
                ControlCall(0x40, 0x04, 0x0008, 1),
                ControlCall(0x40, 0x01, 0x0303, 1),
            ),
            transport.controlCalls,
        )
    }

    @Test
    fun openPort_ft232h_putsTheChannelIntoTheBaudRateIndex() {
        transport.descriptors = TestDevices.deviceDescriptor(0x0403, 0x6014, 0x0900)

        FtdiDriver(TestDevices.ft232h).openPort(transport)

        assertEquals(ControlCall(0x40, 0x03, 0x001A, 0x0001), transport.controlCalls[2])
    }

    @Test
    fun openPort_secondChannelOfFt2232h_addressesChannelBWithTheThirdSubDivisorBitInTheHighByte() {
        transport.descriptors = TestDevices.deviceDescriptor(0x0403, 0x6010, 0x0700)

        FtdiDriver(TestDevices.ft2232h).openPort(transport, portIndex = 1, settings = LineSettings(baudRate = 9573, dtr = false, rts = false))

        assertEquals(listOf(1), transport.claimed)
        assertEquals(
            listOf(
                ControlCall(0x40, 0x00, 0x0000, 2),
                ControlCall(0x40, 0x09, 0x0001, 2),
                ControlCall(0x40, 0x03, 0x0139, 0x0102),
                ControlCall(0x40, 0x04, 0x0008, 2),
                ControlCall(0x40, 0x01, 0x0300, 2),
            ),
            transport.controlCalls,
        )
    }

    @Test
    fun configure_7O2_encodesDataParityAndStopBits() {
        val port = openFt232r()
        transport.controlCalls.clear()

        port.configure(LineSettings(baudRate = 9600, dataBits = 7, parity = Parity.ODD, stopBits = StopBits.TWO))

        assertEquals(
            listOf(
                ControlCall(0x40, 0x03, 0x4138, 0x0000),
                ControlCall(0x40, 0x04, 0x1107, 1),
                ControlCall(0x40, 0x01, 0x0303, 1),
            ),
            transport.controlCalls,
        )
    }

    @Test
    fun configure_sixDataBits_throwsUnsupportedAndSendsNothing() {
        val port = openFt232r()
        transport.controlCalls.clear()

        try {
            port.configure(LineSettings(dataBits = 6))
            fail("accepted 6 data bits")
        } catch (e: UnsupportedSettingException) {
            assertEquals("FTDI chips send 7 or 8 data bits, not 6", e.message)
        }
        assertEquals(emptyList<ControlCall>(), transport.controlCalls)
        assertEquals(LineSettings(), port.lineSettings)
    }

    @Test
    fun read_threeFullPackets_strips2StatusBytesFromEachAndReturns186Bytes() {
        val port = openFt232r()
        transport.incoming += Incoming.Data(packet(0) + packet(62) + packet(124))

        val buffer = ByteArray(200)
        val count = port.read(buffer, timeoutMillis = 50)

        assertEquals(186, count)
        assertArrayEquals(ramp(186), buffer.copyOf(186))
    }

    @Test
    fun read_shortLastPacket_stripsItsStatusBytesToo() {
        val port = openFt232r()
        transport.incoming += Incoming.Data(packet(0) + packet(62, payload = 10))

        val buffer = ByteArray(200)

        assertEquals(72, port.read(buffer, timeoutMillis = 50))
        assertArrayEquals(ramp(72), buffer.copyOf(72))
    }

    @Test
    fun read_smallerBufferThanPayload_keepsTheRestForTheNextRead() {
        val port = openFt232r()
        transport.incoming += Incoming.Data(packet(0) + packet(62) + packet(124))
        val first = ByteArray(150)
        val second = ByteArray(100)

        val firstCount = port.read(first, timeoutMillis = 50)
        val secondCount = port.read(second, timeoutMillis = 50)

        assertEquals(150, firstCount)
        assertEquals(36, secondCount)
        assertArrayEquals(ramp(186), first + second.copyOf(36))
        assertEquals("one USB transfer for both reads", 1, transport.bulkInCalls.size)
    }

    @Test
    fun read_200ByteBuffer_asksForFourWholePackets() {
        val port = openFt232r()
        transport.incoming += Incoming.Data(packet(0))

        port.read(ByteArray(200), timeoutMillis = 50)

        assertEquals(listOf(BulkCall(0x81, 256, 50)), transport.bulkInCalls)
    }

    @Test
    fun read_statusOnlyPackets_keepsWaitingWithTheTimeLeftUntilDataArrives() {
        val port = openFt232r()
        transport.incoming += Incoming.Data(bytes(0x01, 0x60))
        transport.incoming += Incoming.Data(bytes(0x01, 0x60))
        transport.incoming += Incoming.Data(packet(7, payload = 3))

        val buffer = ByteArray(64)
        val count = port.read(buffer, timeoutMillis = 50)

        assertEquals(3, count)
        assertArrayEquals(bytes(7, 8, 9), buffer.copyOf(3))
        assertEquals(3, transport.bulkInCalls.size)
    }

    @Test
    fun read_onlyStatusPacketsUntilTheDeadline_returnsZero() {
        val port = openFt232r()
        transport.incoming += Incoming.Data(bytes(0x01, 0x60))

        val count = port.read(ByteArray(64), timeoutMillis = 50)

        assertEquals(0, count)
        assertEquals("64 payload bytes need 2 packets", listOf(BulkCall(0x81, 128, 50), BulkCall(0x81, 128, 50)), transport.bulkInCalls)
    }
}
