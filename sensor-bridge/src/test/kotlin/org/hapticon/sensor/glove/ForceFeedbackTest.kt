package org.hapticon.sensor.glove

import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import org.hapticon.sensor.live.CommandWriter
import org.hapticon.sensor.live.SessionState
import org.hapticon.sensor.live.SensorSession
import org.hapticon.testing.TEST_UNO
import org.hapticon.testing.TestUsbDevices
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.testing.FakeSerialPort
import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.After
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

/** Force feedback from the glove source through the session's command writer to the serial port. */
class ForceFeedbackTest {
    // Writes run on the calling thread, so the test sees them at once.
    private val session = SensorSession(TestUsbDevices(), commands = CommandWriter { it.run() })
    private val glove = SessionGloveSource(session)
    private val port = FakeSerialPort()

    @After
    fun tearDown() = session.disconnect()

    @Test
    fun lucidGlovesStream_getsTheServoValuesAsALucidCommand() = runBlocking {
        session.start(port, TEST_UNO, SensorProtocol.LUCID_GLOVES, 115_200)

        assertTrue(glove.acceptsForceFeedback.first())
        assertTrue(glove.forceFeedback.send(intArrayOf(0, 250, 500, 750, 1000)))

        assertEquals("A0B250C500D750E1000\n", String(port.writtenBytes(), Charsets.US_ASCII))
        assertEquals(1L, session.commandsSent)
    }

    @Test
    fun csvStream_takesNoForceFeedbackAndNothingIsWritten() = runBlocking {
        session.start(port, TEST_UNO, SensorProtocol.CSV, 115_200)

        assertFalse(glove.acceptsForceFeedback.first())
        assertFalse(glove.forceFeedback.send(intArrayOf(0, 250, 500, 750, 1000)))

        assertEquals(0, port.writtenBytes().size)
    }

    @Test
    fun noStream_sendsNothing() {
        assertFalse(glove.forceFeedback.send(intArrayOf(0, 0, 0, 0, 0)))
        assertFalse(session.send(byteArrayOf(1)))
    }

    @Test
    fun servoValueAboveTheLimit_isRefusedBeforeAnythingIsWritten() {
        session.start(port, TEST_UNO, SensorProtocol.LUCID_GLOVES, 115_200)

        assertThrows(SafetyLimitException::class.java) { glove.forceFeedback.send(intArrayOf(0, 0, 1001, 0, 0)) }

        assertEquals(0, port.writtenBytes().size)
    }

    @Test
    fun stalledBoard_countsTheLostCommandAndReportsItWithoutStoppingTheStream() {
        session.start(port, TEST_UNO, SensorProtocol.LUCID_GLOVES, 115_200)
        port.stallWritesAfter(4)

        assertTrue(glove.forceFeedback.send(intArrayOf(10, 20, 30, 40, 50)))

        assertEquals(0L, session.commandsSent)
        assertEquals(1L, session.commandsLost)
        assertEquals("wrote 4 of 16 bytes before the 100 ms deadline", session.writeError.value)
        assertTrue(session.state.value is SessionState.Streaming)
    }

    @Test
    fun queuedCommands_newestReplacesOneNotYetWritten() {
        val queued = ArrayList<Runnable>()
        val slowSession = SensorSession(TestUsbDevices(), commands = CommandWriter { queued += it })
        slowSession.start(port, TEST_UNO, SensorProtocol.LUCID_GLOVES, 115_200)
        try {
            assertTrue(slowSession.send("first\n".toByteArray()))
            assertTrue(slowSession.send("second\n".toByteArray()))
            assertEquals(1, queued.size)

            queued.single().run()

            assertEquals(listOf("second\n"), port.writes().map { String(it) })
            assertNull(slowSession.writeError.value)
        } finally {
            slowSession.disconnect()
        }
    }

    @Test
    fun stream_sendsChangesAtMostEvery50MsAndReleasesAtOnce() {
        val stream = ForceFeedbackStream()
        val sent = ArrayList<List<Int>>()
        val sink = ForceFeedbackSink { sent += it.toList(); true }
        val servos = IntArray(HandRegion.entries.size)
        fun set(thumb: Int, index: Int, middle: Int, ring: Int, pinkie: Int) {
            servos[HandRegion.THUMB.ordinal] = thumb
            servos[HandRegion.INDEX.ordinal] = index
            servos[HandRegion.MIDDLE.ordinal] = middle
            servos[HandRegion.RING.ordinal] = ring
            servos[HandRegion.PINKY.ordinal] = pinkie
        }

        set(100, 200, 300, 400, 500)
        stream.update(servos, 0, sink)
        stream.update(servos, 60_000_000, sink) // unchanged: not resent
        set(110, 200, 300, 400, 500)
        stream.update(servos, 70_000_000, sink) // 10 ms after the last command: too soon
        stream.update(servos, 110_000_000, sink) // 50 ms after: goes out
        set(0, 0, 0, 0, 0)
        stream.update(servos, 111_000_000, sink) // release: at once

        assertEquals(
            listOf(listOf(100, 200, 300, 400, 500), listOf(110, 200, 300, 400, 500), listOf(0, 0, 0, 0, 0)),
            sent,
        )
        assertEquals(3L, stream.commands)
        assertArrayEquals(intArrayOf(0, 0, 0, 0, 0), stream.lastSentValues())
    }
}
