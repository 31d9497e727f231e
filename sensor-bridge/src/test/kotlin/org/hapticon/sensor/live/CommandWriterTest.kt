package org.hapticon.sensor.live

import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.grains.FirmwareCommands
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.grains.setGrains
import org.hapticon.sensor.grains.stimulate
import org.hapticon.testing.FakeSerialPort
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.Cobs
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertSame
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

/**
 * The command writer on its own, with writes held until the test runs them and a clock the test moves: the order
 * of events and settings, per-key coalescing, the bounded event queue, ack matching and the ack timeout.
 */
class CommandWriterTest {
    private val held = ArrayList<Runnable>()
    private var now = 1_000_000_000L
    private val writer = CommandWriter(executor = { held += it }, clock = { now }, eventCapacity = 3)
    private val port = FakeSerialPort()
    private val encoder = FramedEncoder()
    private val range = FirmwareForceRange.ofAdcBits(10)

    private fun grains(count: Int) = FirmwareGrainParams.wholeArrayCheck(List(9) { 60 }, range).copy(grainCount = count)

    /** The raw frame of a written command: COBS undone, the delimiter dropped. */
    private fun raw(written: ByteArray): List<Int> = Cobs.decode(written.copyOf(written.size - 1))!!.map { it.toInt() and 0xFF }

    private fun runWrites() {
        while (held.isNotEmpty()) held.removeAt(0).run()
    }

    private fun wire(encode: (FramedEncoder, ByteArray) -> Int, sequence: Int): ByteArray {
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        return buffer.copyOf(encode(FramedEncoder(sequence), buffer))
    }

    @Test
    fun stimulateFollowedAtOnceBySettings_isWrittenFirst_andOnlyTheNewestSettingFollows() {
        val stimulus = FirmwareStimulus(electrode = 2, step = 60)
        val stim = writer.submit(port, FirmwareCommands.stimulate(encoder, stimulus))
        val first = writer.submit(port, FirmwareCommands.setGrains(encoder, grains(9)))
        val second = writer.submit(port, FirmwareCommands.setGrains(encoder, grains(39)))

        assertEquals("one drain for the whole queue", 1, held.size)
        runWrites()

        // Sequence 0 is the stimulus, 1 the superseded settings (never written), 2 the newest settings.
        assertEquals(
            listOf(wire({ e, b -> e.stimulate(stimulus, b) }, 0).toList(), wire({ e, b -> e.setGrains(grains(39), b) }, 2).toList()),
            port.writes().map { it.toList() },
        )
        assertEquals(CommandState.Sent(isFinal = false), stim.state.value)
        assertSame(CommandState.Superseded, first.state.value)
        assertEquals(CommandState.Sent(isFinal = false), second.state.value)
        assertEquals(CommandCounts(sent = 2, superseded = 1), writer.counts())
    }

    @Test
    fun settingSentBeforeAStimulus_andReplacedAfterIt_isWrittenAfterTheStimulus() {
        writer.submit(port, FirmwareCommands.setGrains(encoder, grains(9)))
        writer.submit(port, FirmwareCommands.stimulate(encoder, FirmwareStimulus(0, 60)))
        writer.submit(port, FirmwareCommands.setGrains(encoder, grains(19)))
        runWrites()

        // Byte 1 of a raw frame is its type: STIMULATE 0x14, then SET_GRAINS 0x13.
        assertEquals(listOf(0x14, 0x13), port.writes().map { raw(it)[1] })
    }

    @Test
    fun burstOfSettings_coalescesToTheNewest() {
        val handles = (1..5).map { writer.submit(port, FirmwareCommands.setGrains(encoder, grains(it * 5))) }
        runWrites()

        assertEquals(1, port.writes().size)
        assertArrayEquals(wire({ e, b -> e.setGrains(grains(25), b) }, 4), port.writes().single())
        assertEquals(List(4) { CommandState.Superseded }, handles.dropLast(1).map { it.state.value })
        assertEquals(CommandCounts(sent = 1, superseded = 4), writer.counts())
    }

    @Test
    fun fullEventQueue_refusesTheNextStimulusWithAClearError_andCountsIt() {
        val queued = (0 until 3).map { writer.submit(port, FirmwareCommands.stimulate(encoder, FirmwareStimulus(it, 60))) }
        val refused = writer.submit(port, FirmwareCommands.stimulate(encoder, FirmwareStimulus(3, 61)))

        assertEquals(
            CommandState.Overflowed("3 commands are already waiting for the board: it is not keeping up"),
            refused.state.value,
        )
        assertEquals(
            "Not sent: the 200 ms stimulus on electrode 4 at 0.824 mA: 3 commands are already waiting for the board: it is not keeping up",
            writer.commandError.value,
        )
        // A setting still fits: settings take one slot per key, not an event slot.
        writer.submit(port, FirmwareCommands.setGrains(encoder, grains(9)))
        runWrites()

        assertEquals(4, port.writes().size)
        assertEquals(listOf(0, 1, 2), port.writes().take(3).map { raw(it)[4] }) // each stimulus's electrode byte
        queued.forEach { assertEquals(CommandState.Sent(isFinal = false), it.state.value) }
        assertEquals(1L, writer.counts().overflowed)
        // Once written, the queue has room again.
        writer.submit(port, FirmwareCommands.stimulate(encoder, FirmwareStimulus(3, 61)))
        runWrites()
        assertEquals(5, port.writes().size)
    }

    @Test
    fun ackWithTheCommandsSequence_acknowledgesIt_otherSequencesAreCountedUnmatched() {
        val handle = writer.submit(port, FirmwareCommands.stimulate(FramedEncoder(41), FirmwareStimulus(4, 80)))
        runWrites()

        writer.onAck(40, AckStatus.OK, 0)
        assertEquals(CommandState.Sent(isFinal = false), handle.state.value)
        writer.onAck(41, AckStatus.OK, 0)

        assertSame(CommandState.Acknowledged, handle.state.value)
        assertEquals(CommandCounts(sent = 1, acknowledged = 1, unmatchedAcks = 1), writer.counts())
        assertNull(writer.commandError.value)
    }

    @Test
    fun nackWithReason_rejectsTheCommandAndSaysWhyInOneLine() {
        val handle = writer.submit(port, FirmwareCommands.stimulate(encoder, FirmwareStimulus(0, 60)))
        runWrites()

        writer.onAck(0, AckStatus.OUT_OF_RANGE, 9)

        assertEquals(CommandState.Rejected(AckStatus.OUT_OF_RANGE, 9, "a stimulus outside 1..1000 ms"), handle.state.value)
        assertEquals("The board refused the 200 ms stimulus on electrode 1 at 0.810 mA: a stimulus outside 1..1000 ms", writer.commandError.value)
        assertEquals(1L, writer.counts().rejected)
    }

    @Test
    fun missingAck_timesOutAtTheDeadline_andALateAckChangesNothing() {
        val handle = writer.submit(port, FirmwareCommands.setGrains(encoder, grains(39)))
        runWrites()

        now += (CommandWriter.ACK_TIMEOUT_MILLIS - 1) * 1_000_000
        assertEquals(0, writer.expireOverdue())
        assertEquals(CommandState.Sent(isFinal = false), handle.state.value)
        now += 1_000_000
        assertEquals(1, writer.expireOverdue())

        assertEquals(CommandState.TimedOut("no acknowledgement within 500 ms"), handle.state.value)
        assertEquals("No answer from the board to the grain settings (39 grains on 9 electrodes): no acknowledgement within 500 ms", writer.commandError.value)
        writer.onAck(0, AckStatus.OK, 0)
        assertEquals(CommandState.TimedOut("no acknowledgement within 500 ms"), handle.state.value)
        assertEquals(CommandCounts(sent = 1, timedOut = 1, unmatchedAcks = 1), writer.counts())
        assertEquals(0, writer.awaitingAcks())
    }

    @Test
    fun secondCommandWithTheSameSequence_endsTheFirstAsUnanswerable_insteadOfLeavingItWaitingForever() {
        val first = writer.submit(port, FirmwareCommands.stimulate(FramedEncoder(3), FirmwareStimulus(0, 60)))
        val second = writer.submit(port, FirmwareCommands.stimulate(FramedEncoder(3), FirmwareStimulus(1, 60)))
        runWrites()

        assertEquals(CommandState.TimedOut("a later command reused sequence number 3 before the board answered"), first.state.value)
        writer.onAck(3, AckStatus.OK, 0)
        assertSame(CommandState.Acknowledged, second.state.value)
        assertEquals(CommandCounts(sent = 2, acknowledged = 1, timedOut = 1), writer.counts())
    }

    @Test
    fun failedWrite_isNotAwaitingAnAck() {
        port.stallWritesAfter(3)
        val handle = writer.submit(port, FirmwareCommands.stimulate(encoder, FirmwareStimulus(0, 60)))
        runWrites()

        assertTrue(handle.state.value is CommandState.WriteFailed)
        assertEquals(0, writer.awaitingAcks())
        assertEquals(CommandCounts(lost = 1), writer.counts())
    }

    @Test
    fun cap_exactly2point7mA_isQueuedAsStep200_justPastAndNaN_areRefusedBeforeAnythingIsQueued() {
        val atCap = FirmwareStimulus(electrode = 8, step = AmplitudeSteps.stepAtLeast(2.7))
        val command = FirmwareCommands.stimulate(encoder, atCap)
        assertEquals(listOf(200), command.stimulationSteps)
        writer.submit(port, command)
        runWrites()
        // Raw frame: version, type, sequence u16, then electrode 8 and step 200.
        assertEquals(listOf(8, 200), raw(port.writes().single()).slice(4..5))

        for (bad in listOf(2.7 + 1e-9, Double.NaN)) {
            assertThrows(SafetyLimitException::class.java) { FirmwareStimulus(0, AmplitudeSteps.stepAtLeast(bad)) }
        }
        // Hand-built bytes cannot bypass the cap either: the command itself checks its steps.
        assertThrows(SafetyLimitException::class.java) {
            OutgoingCommand(byteArrayOf(1), "a hand-built stimulus", settingKey = null, ackSequence = 0, stimulationSteps = listOf(201))
        }
        assertEquals(1, port.writes().size)
        assertEquals(0, held.size)
    }
}
