package org.hapticon.app.feature.study

import androidx.compose.ui.test.assertIsNotEnabled
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithText
import org.hapticon.app.feature.sensors.ElectrodeLevelsStore
import org.hapticon.app.sensors.HubStimulatorLink
import org.hapticon.app.sensors.StimulatorLink
import org.hapticon.app.feature.sensors.TestStimulatorLink
import org.hapticon.testing.TEST_UNO
import org.hapticon.testing.TestUsbDevices
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.live.CommandWriter
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.port.FakeSerialPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.app.gesture.MainDispatcherRule
import org.hapticon.sensor.safety.SafetyLimitException
import org.hapticon.study.compliance.ComplianceStudy
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import java.io.File

/** Shaping Compliance's study run from the Study tab: conditions on the board at the calibrated levels, answers on disk. */
@RunWith(RobolectricTestRunner::class)
class ComplianceStudyRunTest {
    @get:Rule
    val folder = TemporaryFolder()

    @get:Rule
    val main = MainDispatcherRule()

    @get:Rule
    val compose = createComposeRule()

    private val levels = listOf(70, 71, 72, 73, 74, 75, 76, 77, 78)

    private fun ComplianceViewModel.state(): ComplianceUiState {
        main.dispatcher.scheduler.runCurrent()
        return uiState.value
    }

    @Test
    fun session_everyConditionOnceOnTheBoard_answersSyncedToCsv_meansAtTheEnd() {
        val link = TestStimulatorLink(ready = true)
        val dir = File(folder.root, "compliance")
        val viewModel = ComplianceViewModel(link, { levels }, dir, io = main.dispatcher)
        viewModel.setParticipant("p7")
        viewModel.setParticipantIndex(2)
        viewModel.setRepetitions(1)
        viewModel.start()

        val expectedOrder = ComplianceStudy.PROTOCOL.copy(repetitions = 1).trials(2)
        for ((i, trial) in expectedOrder.withIndex()) {
            val state = viewModel.state() as ComplianceUiState.Trial
            assertEquals(trial, state.trial)
            assertTrue(state.sent)
            val params = link.sent[i]
            assertEquals(trial.condition.grains, params.grainCount)
            assertEquals(trial.condition.mask.pattern, params.pattern)
            assertEquals(levels, params.steps)
            viewModel.answer(if (trial.condition.grains == 39) "20" else "10")
        }
        val done = viewModel.state() as ComplianceUiState.Done
        assertEquals(20, done.answers)
        assertEquals(20, link.sent.size)
        // One participant: normalised by their own geometric mean times the grand one, i.e. unchanged.
        assertEquals(20.0, done.means.getValue("g39-triangle"), 1e-9)
        assertEquals(10.0, done.means.getValue("g0-large-square"), 1e-9)

        val lines = File(dir, "p7.csv").readLines()
        assertEquals(ComplianceViewModel.CSV_HEADER, lines[0])
        val first = expectedOrder[0]
        assertEquals("p7,0,${first.condition.id},${first.condition.grains},${first.condition.mask.name.lowercase()},0,${if (first.condition.grains == 39) 20.0 else 10.0}", lines[1])
        assertEquals(21, lines.size)
    }

    @Test
    fun answer_notANumberZeroOrUnsent_isRefusedAndNothingIsWritten() {
        val link = TestStimulatorLink(ready = false)
        val dir = File(folder.root, "compliance")
        val viewModel = ComplianceViewModel(link, { levels }, dir, io = main.dispatcher)
        viewModel.setParticipant("p1")
        viewModel.start()
        assertEquals("Connect the board (Framed protocol) to render the condition", viewModel.state().message)
        viewModel.answer("5")
        assertEquals("The condition has not reached the board yet", viewModel.state().message)

        link.ready.value = true
        viewModel.sendCondition()
        for (bad in listOf("soft", "0", "-3", "NaN", "Infinity")) {
            viewModel.answer(bad)
            assertEquals(bad, "Type a positive number, e.g. 10", viewModel.state().message)
            assertEquals(0, (viewModel.state() as ComplianceUiState.Trial).trial.index)
        }
        assertTrue(!File(dir, "p1.csv").exists())
    }

    @Test
    fun start_withoutCalibrationOrName_isRefused() {
        val store = ElectrodeLevelsStore(File(folder.root, ElectrodeLevelsStore.FILE_NAME))
        val viewModel = ComplianceViewModel(TestStimulatorLink(ready = true), store::load, folder.root, io = main.dispatcher)
        viewModel.start()
        assertEquals("Name the participant with letters, digits, - or _", viewModel.state().message)
        viewModel.setParticipant("p2")
        viewModel.start()
        assertEquals("Calibrate the electrodes first: Sensors → Electrotactile array", viewModel.state().message)

        store.save(levels)
        viewModel.setParticipant("p2")
        assertEquals(levels, (viewModel.state() as ComplianceUiState.Setup).levels)
        viewModel.start()
        assertTrue(viewModel.state() is ComplianceUiState.Trial)
    }

    @Test
    fun levelsStore_refusesPastTheCapAndReadsADamagedFileAsNone() {
        val file = File(folder.root, ElectrodeLevelsStore.FILE_NAME)
        val store = ElectrodeLevelsStore(file)
        assertNull(store.load())
        store.save(List(9) { 200 })
        assertEquals(List(9) { 200 }, store.load())
        assertThrows(SafetyLimitException::class.java) { store.save(List(8) { 60 } + 201) }
        assertEquals(List(9) { 200 }, store.load())
        file.writeText("60,60,60,60,60,60,60,60,201")
        assertNull(store.load())
        file.writeText("60,60,NaN")
        assertNull(store.load())
    }

    @Test
    fun answer_isSyncedOffMain_aDoubleTapWritesOnce_aFailedWriteKeepsTheTrial() {
        val link = TestStimulatorLink(ready = true)
        val dir = File(folder.root, "compliance")
        var stored: List<Int> = levels
        val viewModel = ComplianceViewModel(link, { stored }, dir, io = main.dispatcher)
        viewModel.setParticipant("p5")
        viewModel.start()
        val first = viewModel.state() as ComplianceUiState.Trial
        // Two taps before the first answer is synced: one line, one step forward.
        viewModel.answer("10")
        viewModel.answer("12")
        val second = viewModel.state() as ComplianceUiState.Trial
        assertEquals(first.trial.index + 1, second.trial.index)
        assertEquals(listOf(ComplianceViewModel.CSV_HEADER), File(dir, "p5.csv").readLines().take(1))
        assertEquals(2, File(dir, "p5.csv").readLines().size)
        assertTrue(File(dir, "p5.csv").readLines()[1].endsWith(",10.0"))
        // A calibration stored mid-session applies to the next session, not to this one's remaining trials.
        stored = List(9) { 90 }
        viewModel.sendCondition()
        assertEquals(levels, link.sent.last().steps)

        // The answers folder cannot be written (a file stands where it should be): the trial stays, and says so.
        val blocked = folder.newFile("blocked")
        val failing = ComplianceViewModel(link, { levels }, blocked, io = main.dispatcher)
        failing.setParticipant("p6")
        failing.start()
        val trial = failing.state() as ComplianceUiState.Trial
        failing.answer("10")
        val after = failing.state() as ComplianceUiState.Trial
        assertEquals(trial.trial, after.trial)
        assertTrue(after.message, after.message!!.startsWith("Not saved (") && after.message!!.endsWith("): give the answer again"))
    }

    @Test
    fun condition_usesTheBoardsAnnouncedRange_andNoRangeSendsNothing() {
        val link = TestStimulatorLink(ready = true, range = FirmwareForceRange.ofAdcBits(12))
        val viewModel = ComplianceViewModel(link, { levels }, File(folder.root, "compliance"), io = main.dispatcher)
        viewModel.setParticipant("p3")
        viewModel.start()
        viewModel.state() // the calibration is read off the main thread, then the first condition goes out
        val first = link.sent.single()
        assertEquals(0 to 4095, first.minForce to first.maxForce)

        // A board whose force channel is in physical units announces no full scale: nothing is guessed or sent.
        link.range = null
        viewModel.sendCondition()
        assertEquals(1, link.sent.size)
        assertEquals(StimulatorLink.NO_FORCE_RANGE, viewModel.state().message)
        assertFalse((viewModel.state() as ComplianceUiState.Trial).sent)
    }

    @Test
    fun session_overTheSerialSession_writesEachConditionsSetGrains_decodedFromTheWire() {
        // A 12-bit framed board announces itself; the view model goes through the real link, session and writer.
        val hub = SensorSession(TestUsbDevices(), commands = CommandWriter { it.run() })
        val port = FakeSerialPort()
        val info = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val infoLength = FramedEncoder().deviceInfo(DeviceInfo(1, 0, 0, 12, 1000, 0, listOf(ChannelUnit.RAW), "board12"), info)
        port.enqueue(info.copyOf(infoLength))
        try {
            hub.start(port, TEST_UNO, SensorProtocol.FRAMED, 115_200)
            val deadline = System.nanoTime() + 10_000_000_000
            while (hub.currentInfo()?.adcBits != 12 && System.nanoTime() < deadline) Thread.sleep(5)
            assertEquals(12, hub.currentInfo()?.adcBits)

            val viewModel = ComplianceViewModel(HubStimulatorLink(hub), { levels }, File(folder.root, "compliance"), io = main.dispatcher)
            viewModel.setParticipant("p4")
            viewModel.setRepetitions(1)
            viewModel.start()
            viewModel.state()
            val order = ComplianceStudy.PROTOCOL.copy(repetitions = 1).trials(0)
            repeat(order.size - 1) {
                viewModel.answer("10")
                viewModel.state() // synced off the main thread, then the next condition goes out
            }

            val frames = splitFrames(port.writtenBytes())
            assertEquals(order.size, frames.size)
            for ((i, trial) in order.withIndex()) {
                val frame = unCobs(frames[i])
                assertEquals("CRC-16/CCITT-FALSE, high byte first", crc16(frame.dropLast(2)), (frame[frame.size - 2] shl 8) or frame.last())
                assertEquals(listOf(1, 0x13, i, 0), frame.take(4))
                val payload = frame.subList(4, frame.size - 2)
                assertEquals(trial.condition.id, trial.condition.grains, payload[0])
                assertEquals(4095, payload[4] or (payload[5] shl 8))
                val bits = payload[6] or (payload[7] shl 8)
                assertEquals(trial.condition.id, trial.condition.mask.pattern.bits, bits)
                assertEquals(levels, payload.subList(8, 17))
            }
        } finally {
            hub.disconnect()
        }
    }

    /** COBS undone (docs/protocols.md), written apart from sensor-bridge's decoder. */
    private fun unCobs(encoded: ByteArray): List<Int> {
        val out = ArrayList<Int>()
        var i = 0
        while (i < encoded.size) {
            val code = encoded[i].toInt() and 0xFF
            for (k in 1 until code) out += encoded[i + k].toInt() and 0xFF
            i += code
            if (code < 0xFF && i < encoded.size) out += 0
        }
        return out
    }

    private fun crc16(bytes: List<Int>): Int {
        var crc = 0xFFFF
        for (b in bytes) {
            crc = crc xor (b shl 8)
            repeat(8) { crc = if (crc and 0x8000 != 0) (crc shl 1) xor 0x1021 else crc shl 1 }
            crc = crc and 0xFFFF
        }
        return crc
    }

    /** The COBS frames of [wire], each without its 0x00 delimiter. */
    private fun splitFrames(wire: ByteArray): List<ByteArray> {
        val frames = ArrayList<ByteArray>()
        var start = 0
        for (i in wire.indices) {
            if (wire[i].toInt() == 0) {
                frames += wire.copyOfRange(start, i)
                start = i + 1
            }
        }
        return frames
    }

    @Test
    fun screen_trialNotSent_nextIsDisabled() {
        val trial = ComplianceStudy.PROTOCOL.trials(0).first()
        val state = ComplianceUiState.Trial("p1", trial, 60, ComplianceStudy.PROTOCOL.instructions, sent = false, boardReady = false, message = null)
        compose.setContent { ComplianceScreen(state, ComplianceActions()) }
        compose.onNodeWithText("p1 · trial 1 of 60").assertExists()
        compose.onNodeWithText("Next").assertIsNotEnabled()
        compose.onNodeWithText("Waiting for the board…").assertExists()
        compose.onNodeWithText("Researcher: end the session").assertExists()
    }
}
