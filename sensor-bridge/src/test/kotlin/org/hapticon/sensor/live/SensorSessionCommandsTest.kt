package org.hapticon.sensor.live

import org.hapticon.sensor.grains.FirmwareCommands
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.testing.FakeSerialPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.Cobs
import org.hapticon.sensor.protocol.framed.Crc16
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.testing.TEST_UNO
import org.hapticon.testing.TestUsbDevices
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertSame
import org.junit.Assert.assertTrue
import org.junit.Test

/**
 * Commands through the live session: the board's ack and NACK frames, read on the session's own reading thread,
 * settle the command they answer; a malformed ack is counted and the stream goes on; the counters show it all.
 */
class SensorSessionCommandsTest {
    private val session = SensorSession(TestUsbDevices(), commands = CommandWriter { it.run() })
    private val port = FakeSerialPort()
    private val board = FramedEncoder() // the device's side: its own sequence numbers

    @After
    fun tearDown() = session.disconnect()

    private fun ack(sequence: Int, status: AckStatus, detail: Int): ByteArray {
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        return buffer.copyOf(board.ack(sequence, status, detail, buffer))
    }

    /** An ack frame with a good CRC and a 3-byte payload (one short): well framed, impossible to match. */
    private fun shortAck(): ByteArray {
        val raw = byteArrayOf(FramedProtocol.VERSION.toByte(), 0x03, 9, 0, 0, 0, 0)
        val crc = Crc16.compute(raw)
        val frame = raw + byteArrayOf((crc ushr 8).toByte(), crc.toByte())
        val out = ByteArray(Cobs.maxEncodedLength(frame.size) + 1)
        val n = Cobs.encode(frame, 0, frame.size, out, 0)
        return out.copyOf(n + 1) // the trailing 0x00 delimiter is already there
    }

    private fun <T> awaitValue(timeoutMillis: Long = 5_000, read: () -> T, done: (T) -> Boolean): T {
        val deadline = System.nanoTime() + timeoutMillis * 1_000_000
        var value = read()
        while (!done(value) && System.nanoTime() < deadline) {
            Thread.sleep(2)
            value = read()
        }
        return value
    }

    @Test
    fun ackFromTheBoard_acknowledgesTheStimulus_andIsCounted() {
        session.start(port, TEST_UNO, SensorProtocol.FRAMED, 115_200)
        val handle = session.submit(FirmwareCommands.stimulate(FramedEncoder(7), FirmwareStimulus(1, 70)))!!

        port.enqueue(ack(7, AckStatus.OK, 0))

        assertSame(CommandState.Acknowledged, awaitValue(read = { handle.state.value }) { it.isFinal })
        val counters = session.snapshot().counters
        assertEquals(1L, counters.commandsSent)
        assertEquals(1L, counters.commandsAcknowledged)
        assertEquals(0L, counters.unmatchedAcks)
        assertNull(session.commandError.value)
    }

    @Test
    fun nackFromTheBoard_rejectsWithTheFirmwaresReason_inOneLine() {
        session.start(port, TEST_UNO, SensorProtocol.FRAMED, 115_200)
        val handle = session.submit(FirmwareCommands.stimulate(FramedEncoder(), FirmwareStimulus(1, 70)))!!

        port.enqueue(ack(0, AckStatus.OUT_OF_RANGE, 5))

        val state = awaitValue(read = { handle.state.value }) { it.isFinal }
        assertEquals(CommandState.Rejected(AckStatus.OUT_OF_RANGE, 5, "an amplitude step past 200 (2.7 mA)"), state)
        assertEquals(
            "The board refused the 200 ms stimulus on electrode 2 at 0.945 mA: an amplitude step past 200 (2.7 mA)",
            session.commandError.value,
        )
        assertEquals(1L, session.snapshot().counters.commandsRejected)
    }

    @Test
    fun malformedAck_isCountedNotFatal_andTheNextGoodAckStillMatches() {
        session.start(port, TEST_UNO, SensorProtocol.FRAMED, 115_200)
        val handle = session.submit(FirmwareCommands.stimulate(FramedEncoder(9), FirmwareStimulus(0, 60)))!!

        port.enqueue(shortAck() + byteArrayOf(0x55, 0x13, 0x00) + ack(9, AckStatus.OK, 0))

        assertSame(CommandState.Acknowledged, awaitValue(read = { handle.state.value }) { it.isFinal })
        val counters = session.snapshot().counters
        assertEquals(1L, counters.malformedAcks)
        assertEquals("the short ack and the garbage", 2L, counters.badFrames)
        assertEquals(1L, counters.commandsAcknowledged)
        assertTrue(session.state.value is SessionState.Streaming)
    }

    @Test
    fun streamEndsBeforeTheAck_theCommandTimesOutWithTheReason() {
        session.start(port, TEST_UNO, SensorProtocol.FRAMED, 115_200)
        val handle = session.submit(FirmwareCommands.stimulate(FramedEncoder(), FirmwareStimulus(0, 60)))!!

        port.enqueueEnd()

        assertTrue(session.awaitStopped(5_000))
        assertEquals(CommandState.TimedOut("the stream stopped before the board answered"), handle.state.value)
        assertEquals(1L, session.snapshot().counters.commandsTimedOut)
    }

    @Test
    fun noStream_nothingIsSubmitted() {
        assertNull(session.submit(FirmwareCommands.stimulate(FramedEncoder(), FirmwareStimulus(0, 60))))
        assertEquals(0, port.writes().size)
    }
}
