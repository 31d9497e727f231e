package org.hapticon.app.feature.study

import androidx.compose.ui.test.assertIsEnabled
import androidx.compose.ui.test.assertIsNotEnabled
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithTag
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import androidx.compose.ui.test.performTouchInput
import androidx.compose.ui.test.swipe
import androidx.compose.ui.geometry.Offset
import org.hapticon.app.data.ElectrodeLevelsStore
import org.hapticon.app.sensors.SessionStimulatorLink
import org.hapticon.app.sensors.StimulatorLink
import org.hapticon.app.feature.sensors.TestStimulatorLink
import org.hapticon.testing.TEST_UNO
import org.hapticon.testing.TestUsbDevices
import org.hapticon.sensor.electrotactile.ElectrotactileCalibrationResult
import org.hapticon.sensor.electrotactile.StoredCalibration
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.live.CommandWriter
import org.hapticon.sensor.live.SensorSession
import org.hapticon.testing.FakeSerialPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.app.gesture.MainDispatcherRule
import org.hapticon.study.compliance.ComplianceAnswersCsv
import org.hapticon.study.compliance.ComplianceStudy
import org.hapticon.study.compliance.DrawingPoint
import org.hapticon.study.compliance.ShapeDrawings
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNotNull
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import java.io.File
import java.time.Instant

/** Shaping Compliance's study run from the Study tab: calibrated before each repetition, conditions on the board, answers on disk. */
@RunWith(RobolectricTestRunner::class)
class ComplianceStudyRunTest {
    @get:Rule
    val compose = createComposeRule()

    @get:Rule
    val main = MainDispatcherRule()

    @get:Rule
    val folder = TemporaryFolder()

    /** The time the view model sees, moved on by the test. */
    private var now = Instant.parse("2026-12-01T10:00:00Z")

    /** The stored calibration the view model reads. */
    private var stored: StoredCalibration? = null

    /** A calibration finished now, every electrode at [step]. */
    private fun calibrate(step: Int) {
        now = now.plusSeconds(60)
        stored = StoredCalibration(ElectrotactileCalibrationResult(List(9) { step }), now)
    }

    private fun viewModel(link: StimulatorLink, dir: File = File(folder.root, "compliance")) =
        ComplianceViewModel(link, { stored }, dir, File(folder.root, "exports"), io = main.dispatcher, clock = { now })

    private fun ComplianceViewModel.state(): ComplianceUiState {
        main.dispatcher.scheduler.runCurrent()
        return uiState.value
    }

    @Test
    fun published_threeBlocks_eachAfterAFreshCalibration_answersSigned_syncedToCsv() {
        val link = TestStimulatorLink(ready = true)
        val viewModel = viewModel(link)
        calibrate(60) // an old calibration: the session must not use it
        now = now.plusSeconds(30)
        viewModel.setParticipant("p7")
        viewModel.setParticipantIndex(2)
        viewModel.start()

        val order = ComplianceStudy.PROTOCOL.trials(2)
        for ((i, trial) in order.withIndex()) {
            if (i % 12 == 0) {
                val calibrate = viewModel.state() as ComplianceUiState.Calibrate
                assertEquals(trial, calibrate.next)
                assertEquals(i > 0, calibrate.isBreak)
                assertFalse("the stored calibration is older than this step", calibrate.fresh)
                viewModel.continueAfterCalibration()
                assertEquals("Calibrate the electrodes first: the study recalibrates before this repetition", viewModel.state().message)
                // Each repetition at its own calibration's levels (003_8ca1dc8f53472543.txt:152).
                calibrate(70 + i)
                viewModel.refreshCalibration()
                assertTrue((viewModel.state() as ComplianceUiState.Calibrate).fresh)
                viewModel.continueAfterCalibration()
            }
            val state = viewModel.state() as ComplianceUiState.Trial
            assertEquals(trial, state.trial)
            assertTrue(state.sent)
            val params = link.sent.last()
            assertEquals(trial.condition.grains, params.grainCount)
            assertEquals(trial.condition.mask.pattern, params.pattern)
            assertEquals(List(9) { 70 + i / 12 * 12 }, params.steps)
            now = now.plusSeconds(20)
            // Signed ratings against the desk: more compliant positive, less negative, the same 0.
            viewModel.answer(
                when (trial.condition.grains) {
                    39 -> "4"
                    19 -> "1,5"
                    else -> if (trial.repetition == 0) "-1" else "0"
                },
            )
        }
        val done = viewModel.state() as ComplianceUiState.Done
        assertEquals(36, done.answers)
        assertEquals(36, link.sent.size)
        assertEquals("p7-shaping-compliance.csv", done.file.name)
        val lines = done.file.readLines()
        assertEquals(ComplianceAnswersCsv.HEADER, lines[0])
        assertEquals(37, lines.size)
        val first = order[0]
        assertTrue(lines[1], lines[1].startsWith("shaping-compliance,p7,1,1,${first.condition.id},${first.condition.grains},"))
        // Read back as the analysis reads it: 36 ratings, 12 per repetition.
        val read = ComplianceAnswersCsv.read(done.file.readText(), "p7")
        assertEquals(listOf(12, 12, 12), read.ratings.groupBy { it.repetition }.values.map { it.size })
        assertEquals(12, done.medians.size)
        assertNull(done.summaryProblem)
        assertTrue(done.medians.getValue("g39-small-square") > done.medians.getValue("g9-small-square"))

        viewModel.exportAnswers()
        val exported = (viewModel.state() as ComplianceUiState.Done).exported
        assertNotNull(exported)
        assertEquals(done.file.readText(), exported!!.readText())
        assertEquals(File(folder.root, "exports"), exported.parentFile)
    }

    @Test
    fun answer_notANumberOrUnsent_isRefused_zeroAndNegativeAccepted() {
        val link = TestStimulatorLink(ready = false)
        val dir = File(folder.root, "compliance")
        val viewModel = viewModel(link, dir)
        viewModel.setParticipant("p1")
        viewModel.start()
        calibrate(60)
        viewModel.continueAfterCalibration()
        assertEquals("Connect the board (Framed protocol) to render the condition", viewModel.state().message)
        viewModel.answer("5")
        assertEquals("The condition has not reached the board yet", viewModel.state().message)

        link.ready.value = true
        viewModel.sendCondition()
        for (bad in listOf("soft", "NaN", "Infinity", "1.2.3", " ")) {
            viewModel.answer(bad)
            assertEquals(bad, "Type a number: positive if more compliant than the desk, negative if less, 0 if the same", viewModel.state().message)
            assertEquals(0, (viewModel.state() as ComplianceUiState.Trial).trial.index)
        }
        assertFalse(File(dir, "p1-shaping-compliance.csv").exists())
        viewModel.answer("0")
        viewModel.state()
        viewModel.answer("-3")
        assertEquals(2, (viewModel.state() as ComplianceUiState.Trial).trial.index)
        assertEquals(listOf("0.0", "-3.0"), File(dir, "p1-shaping-compliance.csv").readLines().drop(1).map { it.split(',')[8] })
    }

    @Test
    fun task2_yesNoThenDrawing_storedWithTheTrial() {
        val link = TestStimulatorLink(ready = true)
        val viewModel = viewModel(link)
        viewModel.selectProtocol(ComplianceStudy.SHAPES_ID)
        viewModel.setParticipant("p3")
        viewModel.start()
        calibrate(80)
        viewModel.continueAfterCalibration()
        val first = viewModel.state() as ComplianceUiState.Trial
        assertEquals(ComplianceStudy.SHAPES_PROTOCOL, first.protocol)
        assertEquals(39, link.sent.single().grainCount)

        val outline = listOf(DrawingPoint(0.3, 0.3), DrawingPoint(0.7, 0.3), DrawingPoint(0.7, 0.7), DrawingPoint(0.3, 0.7))
        viewModel.answerDrawing(null, listOf(outline))
        assertEquals("First answer: did it feel more compliant than the desk?", viewModel.state().message)
        viewModel.answerDrawing(true, listOf(outline.take(2)))
        assertEquals("Draw the outline of the area where you felt compliance", viewModel.state().message)
        viewModel.answerDrawing(true, listOf(outline, outline.take(2)))
        assertEquals(1, (viewModel.state() as ComplianceUiState.Trial).trial.index)
        // Felt less compliant: kept, without a drawing (the analysis leaves it out, as the paper removed its one).
        viewModel.answerDrawing(false, emptyList())
        val third = viewModel.state() as ComplianceUiState.Trial
        assertEquals(2, third.trial.index)

        val read = ComplianceAnswersCsv.read(File(folder.root, "compliance/p3-shaping-compliance-shapes.csv").readText(), "p3")
        assertEquals(listOf(true, false), read.drawings.map { it.moreCompliant })
        assertEquals(listOf(outline), read.drawings[0].contours)
        assertEquals(first.trial.condition, read.drawings[0].condition)
        assertEquals(ShapeDrawings.encode(listOf(outline)), File(folder.root, "compliance/p3-shaping-compliance-shapes.csv").readLines()[1].split(',')[10])
    }

    @Test
    fun answer_failedWrite_keepsTheTrial_doubleTapWritesOnce() {
        val link = TestStimulatorLink(ready = true)
        val dir = File(folder.root, "compliance")
        val viewModel = viewModel(link, dir)
        viewModel.setParticipant("p5")
        viewModel.start()
        calibrate(65)
        viewModel.continueAfterCalibration()
        val first = viewModel.state() as ComplianceUiState.Trial
        viewModel.answer("10")
        viewModel.answer("12")
        assertEquals(first.trial.index + 1, (viewModel.state() as ComplianceUiState.Trial).trial.index)
        assertEquals(2, File(dir, "p5-shaping-compliance.csv").readLines().size)

        // The answers folder cannot be written (a file stands where it should be): the trial stays, and says so.
        val blocked = folder.newFile("blocked")
        val failing = viewModel(link, blocked)
        failing.setParticipant("p6")
        failing.start()
        failing.continueAfterCalibration() // p5's calibration is older than this step
        calibrate(66)
        failing.continueAfterCalibration()
        val trial = failing.state() as ComplianceUiState.Trial
        failing.answer("10")
        val after = failing.state() as ComplianceUiState.Trial
        assertEquals(trial.trial, after.trial)
        assertTrue(after.message, after.message!!.startsWith("Not saved (") && after.message!!.endsWith("): give the answer again"))
    }

    @Test
    fun start_withoutName_isRefused_andTheStoredCalibrationIsShown() {
        val store = ElectrodeLevelsStore(File(folder.root, ElectrodeLevelsStore.FILE_NAME))
        val viewModel = ComplianceViewModel(TestStimulatorLink(ready = true), store::stored, folder.root, io = main.dispatcher)
        viewModel.start()
        assertEquals("Name the participant with letters, digits, - or _", viewModel.state().message)
        assertNull((viewModel.state() as ComplianceUiState.Setup).calibration)
        store.save(List(9) { 70 })
        viewModel.refreshCalibration()
        assertEquals(List(9) { 70 }, (viewModel.state() as ComplianceUiState.Setup).calibration!!.result.steps)
    }

    @Test
    fun condition_usesTheBoardsAnnouncedRange_andNoRangeSendsNothing() {
        val link = TestStimulatorLink(ready = true, range = FirmwareForceRange.ofAdcBits(12))
        val viewModel = viewModel(link)
        viewModel.setParticipant("p3")
        viewModel.start()
        calibrate(60)
        viewModel.continueAfterCalibration()
        viewModel.state()
        val first = link.sent.single()
        assertEquals(0 to 4095, first.minForce to first.maxForce)
        // The dead time is the grain's own delivery on its electrodes (003_8ca1dc8f53472543.txt:97).
        assertEquals(8000 + 250 * first.pattern.activeCount, first.grainMicros)

        link.range = null
        viewModel.sendCondition()
        assertEquals(1, link.sent.size)
        assertEquals(StimulatorLink.NO_FORCE_RANGE, viewModel.state().message)
        assertFalse((viewModel.state() as ComplianceUiState.Trial).sent)
    }

    @Test
    fun session_overTheSerialSession_writesEachConditionsSetGrains_decodedFromTheWire() {
        // A 12-bit framed board announces itself; the view model goes through the real link, session and writer.
        val session = SensorSession(TestUsbDevices(), commands = CommandWriter { it.run() })
        val port = FakeSerialPort()
        val info = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val infoLength = FramedEncoder().deviceInfo(DeviceInfo(1, 0, 0, 12, 1000, 0, listOf(ChannelUnit.RAW), "board12"), info)
        port.enqueue(info.copyOf(infoLength))
        try {
            session.start(port, TEST_UNO, SensorProtocol.FRAMED, 115_200)
            val deadline = System.nanoTime() + 10_000_000_000
            while (session.currentInfo()?.adcBits != 12 && System.nanoTime() < deadline) Thread.sleep(5)
            assertEquals(12, session.currentInfo()?.adcBits)

            val viewModel = viewModel(SessionStimulatorLink(session))
            viewModel.setParticipant("p4")
            viewModel.start()
            val order = ComplianceStudy.PROTOCOL.trials(0)
            for ((i, _) in order.withIndex()) {
                viewModel.state() // the last answer synced, then the next trial or calibration
                if (i % 12 == 0) {
                    calibrate(60 + i)
                    viewModel.continueAfterCalibration()
                    viewModel.state()
                }
                viewModel.answer("1")
            }
            assertTrue(viewModel.state() is ComplianceUiState.Done)

            val frames = splitFrames(port.writtenBytes())
            assertEquals(order.size, frames.size)
            for ((i, trial) in order.withIndex()) {
                val frame = unCobs(frames[i])
                assertEquals("CRC-16/CCITT-FALSE, high byte first", crc16(frame.dropLast(2)), (frame[frame.size - 2] shl 8) or frame.last())
                assertEquals(listOf(1, 0x13, i, 0), frame.take(4))
                val payload = frame.subList(4, frame.size - 2)
                assertEquals(trial.condition.id, trial.condition.grains, payload[0])
                assertEquals(4095, payload[4] or (payload[5] shl 8))
                assertEquals(trial.condition.id, trial.condition.mask.pattern.bits, payload[6] or (payload[7] shl 8))
                assertEquals(List(9) { 60 + i / 12 * 12 }, payload.subList(8, 17))
                assertEquals(8000 + 250 * trial.condition.mask.pattern.activeCount, payload[19] or (payload[20] shl 8))
            }
        } finally {
            session.disconnect()
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
        val state = ComplianceUiState.Trial("p1", ComplianceStudy.PROTOCOL, trial, 36, sent = false, boardReady = false, message = null)
        compose.setContent { ComplianceScreen(state, ComplianceActions()) }
        compose.onNodeWithText("p1 · repetition 1 of 3 · trial 1 of 36").assertExists()
        compose.onNodeWithText("Next").assertIsNotEnabled()
        compose.onNodeWithText("Waiting for the board…").assertExists()
        compose.onNodeWithText("Compliance (bare desk = 0)").assertExists()
        compose.onNodeWithText("Researcher: end the session").assertExists()
    }

    @Test
    fun screen_drawing_aSwipeIsOneClosedContour_savedWithTheAnswer() {
        val trial = ComplianceStudy.SHAPES_PROTOCOL.trials(0).first()
        val state = ComplianceUiState.Trial("p3", ComplianceStudy.SHAPES_PROTOCOL, trial, 15, sent = true, boardReady = true, message = null)
        var saved: Pair<Boolean?, List<List<DrawingPoint>>>? = null
        compose.setContent { ComplianceScreen(state, ComplianceActions(onDrawing = { more, contours -> saved = more to contours })) }
        compose.onNodeWithText("Save drawing").assertIsNotEnabled()
        compose.onNodeWithText("Yes").performScrollTo().performClick()
        compose.onNodeWithTag(DRAWING_TAG).performScrollTo().performTouchInput {
            swipe(Offset(width * 0.3f, height * 0.3f), Offset(width * 0.7f, height * 0.7f), durationMillis = 400)
        }
        compose.onNodeWithText("Save drawing").performScrollTo().assertIsEnabled().performClick()
        val (more, contours) = saved!!
        assertEquals(true, more)
        assertEquals(1, contours.size)
        val c = contours.single()
        assertTrue("${c.size} points", c.size >= 3)
        assertEquals(0.3, c.first().x, 0.05)
        assertEquals(0.7, c.last().y, 0.05)
    }
}
