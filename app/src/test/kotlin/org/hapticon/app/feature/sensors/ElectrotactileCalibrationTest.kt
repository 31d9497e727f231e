package org.hapticon.app.feature.sensors

import org.hapticon.app.sensors.StimulatorLink
import org.hapticon.app.sensors.SessionStimulatorLink
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.grains.setGrains
import org.hapticon.sensor.grains.stimulate
import org.hapticon.sensor.live.CommandState
import org.hapticon.sensor.live.CommandWriter
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.protocol.SensorProtocol
import androidx.compose.ui.test.assertIsEnabled
import androidx.compose.ui.test.assertIsNotEnabled
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.setValue
import org.hapticon.app.gesture.MainDispatcherRule
import org.hapticon.testing.TEST_UNO
import org.hapticon.testing.TestUsbDevices
import org.hapticon.sensor.electrotactile.ElectrodePattern
import org.hapticon.testing.FakeSerialPort
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNotNull
import org.junit.Assert.assertNull
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** Shaping Compliance's electrotactile calibration driven from the app: steps, the 2.7 mA cap and the whole-array check on the wire. */
@RunWith(RobolectricTestRunner::class)
class ElectrotactileCalibrationTest {
    @get:Rule
    val main = MainDispatcherRule()

    @get:Rule
    val compose = createComposeRule()

    private fun ElectrotactileCalibrationViewModel.state(): ElectrotactileUiState {
        main.dispatcher.scheduler.runCurrent()
        return uiState.value
    }

    @Test
    fun notYet_fromStep60_risesOneStepPerPressAndStopsAtTheCap() {
        val viewModel = ElectrotactileCalibrationViewModel(TestStimulatorLink(ready = false))
        val first = viewModel.state() as ElectrotactileUiState.Electrode
        assertEquals(0, first.electrode)
        assertEquals(60, first.step)
        assertEquals(0.81, first.milliamps, 1e-12)

        viewModel.notYet()
        assertEquals(61, (viewModel.state() as ElectrotactileUiState.Electrode).step)
        assertEquals(0.8235, (viewModel.state() as ElectrotactileUiState.Electrode).milliamps, 1e-12)

        repeat(139) { viewModel.notYet() }
        val atCap = viewModel.state() as ElectrotactileUiState.Electrode
        assertEquals(200, atCap.step)
        assertEquals(2.7, atCap.milliamps, 0.0)
        assertTrue(atCap.atCap)
        assertNull(atCap.message)

        // Just past the cap: refused, stays at 2.7 mA and says so.
        viewModel.notYet()
        val pastCap = viewModel.state() as ElectrotactileUiState.Electrode
        assertEquals(200, pastCap.step)
        assertEquals("Already at the 2.7 mA cap: it cannot go higher", pastCap.message)
    }

    @Test
    fun wholeArrayCheck_sendsSetGrainsWith39GrainsOnAllNineAtTheCalibratedSteps() {
        val link = TestStimulatorLink(ready = false)
        val viewModel = ElectrotactileCalibrationViewModel(link)
        for (electrode in 0 until 9) {
            repeat(electrode) { viewModel.notYet() }
            viewModel.clearAndPainFree()
        }
        val check = viewModel.state() as ElectrotactileUiState.WholeArrayCheck
        assertEquals((60..68).toList(), check.steps)
        assertFalse(check.boardReady)

        viewModel.sendWholeArrayCheck()
        assertEquals(StimulatorLink.NO_BOARD, viewModel.state().message)
        assertTrue(link.sent.isEmpty())

        link.ready.value = true
        assertTrue(viewModel.state().boardReady)
        viewModel.sendWholeArrayCheck()
        val params = link.sent.single()
        assertEquals(39, params.grainCount)
        assertEquals(ElectrodePattern.ALL, params.pattern)
        assertEquals((60..68).toList(), params.steps)
        assertEquals("the 10-bit board's announced range", 0 to 1023, params.minForce to params.maxForce)
        assertTrue((viewModel.state() as ElectrotactileUiState.WholeArrayCheck).sent)

        // Too strong lowers every electrode one step; what the board has is then stale.
        viewModel.tooStrong()
        val lowered = viewModel.state() as ElectrotactileUiState.WholeArrayCheck
        assertEquals((59..67).toList(), lowered.steps)
        assertFalse(lowered.sent)

        viewModel.wholeArrayOk()
        val done = viewModel.state() as ElectrotactileUiState.Done
        assertEquals(67 * 0.0135, done.limitMilliamps!!, 1e-12)
    }

    @Test
    fun wholeArrayCheck_theElectrodeThatStandsOut_isAdjusted_andResent() {
        // The check is adjusted until the sensation is uniform (003_8ca1dc8f53472543.txt:152).
        val link = TestStimulatorLink(ready = true)
        val viewModel = ElectrotactileCalibrationViewModel(link)
        repeat(9) { viewModel.clearAndPainFree() }
        viewModel.weaker() // nothing selected: nothing changes
        assertEquals(List(9) { 60 }, viewModel.state().steps)
        viewModel.selectElectrode(4)
        viewModel.weaker()
        viewModel.weaker()
        viewModel.selectElectrode(0)
        viewModel.stronger()
        val state = viewModel.state() as ElectrotactileUiState.WholeArrayCheck
        assertEquals(0, state.selected)
        assertEquals(listOf(61, 60, 60, 60, 58, 60, 60, 60, 60), state.steps)
        // Each adjustment went to the board at once, the last with both changes.
        assertEquals(3, link.sent.size)
        assertEquals(listOf(61, 60, 60, 60, 58, 60, 60, 60, 60), link.sent.last().steps)
        assertTrue(state.sent)
        viewModel.wholeArrayOk()
        assertEquals(listOf(61, 60, 60, 60, 58, 60, 60, 60, 60), viewModel.state().steps)
    }

    @Test
    fun wholeArrayCheckScreen_tappingACellSelectsIt_andTheButtonsNameIt() {
        var selected = -1
        var weaker = 0
        val state = ElectrotactileUiState.WholeArrayCheck(sent = true, selected = null, steps = List(9) { 60 }, boardReady = true, message = null)
        var shown by mutableStateOf(state)
        compose.setContent { ElectrotactileCalibrationScreen(shown, ElectrotactileActions(onSelectElectrode = { selected = it }, onWeaker = { weaker++ })) }
        compose.onNodeWithText("Tap an electrode to adjust it").assertIsNotEnabled()
        compose.onNodeWithContentDescription("Electrode 5: 0.810 mA").performScrollTo().performClick()
        assertEquals(4, selected)
        shown = state.copy(selected = 4)
        compose.onNodeWithText("Electrode 5 weaker").performScrollTo().assertIsEnabled().performClick()
        compose.onNodeWithText("Electrode 5 stronger").assertIsEnabled()
        assertEquals(1, weaker)
    }

    @Test
    fun everyElectrodeLoweredToZero_doneAllowsNoStimulation() {
        val viewModel = ElectrotactileCalibrationViewModel(TestStimulatorLink(ready = true))
        repeat(9) { viewModel.clearAndPainFree() }
        repeat(60) { viewModel.tooStrong() }
        assertEquals(List(9) { 0 }, viewModel.state().steps)
        viewModel.tooStrong()
        assertEquals(List(9) { 0 }, viewModel.state().steps)
        viewModel.wholeArrayOk()
        assertNull((viewModel.state() as ElectrotactileUiState.Done).limitMilliamps)

        viewModel.restart()
        assertEquals(60, (viewModel.state() as ElectrotactileUiState.Electrode).step)
    }

    @Test
    fun wholeArrayCheck_atTheCapPassesAndOneStepPastIsRefused() {
        val range = FirmwareForceRange.ofAdcBits(10)
        assertEquals(List(9) { 200 }, FirmwareGrainParams.wholeArrayCheck(List(9) { 200 }, range).steps)
        val refused = assertThrows(SafetyLimitException::class.java) {
            FirmwareGrainParams.wholeArrayCheck(List(8) { 200 } + 201, range)
        }
        assertEquals("amplitude step must be in 0..200, was 201", refused.message)
        assertThrows(SafetyLimitException::class.java) { FirmwareGrainParams.wholeArrayCheck(List(8) { 0 } + -1, range) }
    }

    @Test
    fun wholeArrayCheck_takesTheBoardsRange_andAChannelWithoutOneSendsNothing() {
        val link = TestStimulatorLink(ready = true, range = FirmwareForceRange.ofAdcBits(12))
        val viewModel = ElectrotactileCalibrationViewModel(link)
        repeat(9) { viewModel.clearAndPainFree() }
        viewModel.sendWholeArrayCheck()
        assertEquals(0 to 4095, link.sent.single().minForce to link.sent.single().maxForce)

        link.range = null
        viewModel.sendWholeArrayCheck()
        assertEquals(1, link.sent.size)
        assertEquals(StimulatorLink.NO_FORCE_RANGE, viewModel.state().message)
        assertFalse((viewModel.state() as ElectrotactileUiState.WholeArrayCheck).sent)
    }

    @Test
    fun giveStimulus_eachElectrodeAloneAtItsNextStep_200ms() {
        val link = TestStimulatorLink(ready = false)
        val viewModel = ElectrotactileCalibrationViewModel(link)
        viewModel.giveStimulus()
        assertEquals(StimulatorLink.NO_BOARD, viewModel.state().message)
        assertTrue(link.stimuli.isEmpty())

        link.ready.value = true
        viewModel.giveStimulus()
        viewModel.notYet()
        viewModel.giveStimulus()
        assertEquals("Gave 200 ms at 0.824 mA on electrode 1: how did it feel?", viewModel.state().message)
        viewModel.clearAndPainFree()
        repeat(140) { viewModel.notYet() }
        viewModel.giveStimulus()
        assertEquals(listOf(FirmwareStimulus(0, 60), FirmwareStimulus(0, 61), FirmwareStimulus(1, 200)), link.stimuli)

        // The whole-array check is grains, not a single stimulus: nothing more is given.
        repeat(8) { viewModel.clearAndPainFree() }
        viewModel.giveStimulus()
        assertEquals(3, link.stimuli.size)
    }

    @Test
    fun sessionLink_framedStream_writesTheSetGrainsFrame_otherProtocolsWriteNothing() {
        val params = FirmwareGrainParams.wholeArrayCheck(List(9) { 120 }, FirmwareForceRange.ofAdcBits(10))
        val stimulus = FirmwareStimulus(4, 200)
        // One session per stream, writes on the calling thread: no reader of an earlier stream can race the next start.
        val csvSession = SensorSession(TestUsbDevices(), commands = CommandWriter { it.run() })
        val framedSession = SensorSession(TestUsbDevices(), commands = CommandWriter { it.run() })
        try {
            assertNull(SessionStimulatorLink(csvSession).send(params))
            val csvPort = FakeSerialPort()
            csvSession.start(csvPort, TEST_UNO, SensorProtocol.CSV, 115_200)
            assertNull(SessionStimulatorLink(csvSession).send(params))
            assertEquals(0, csvPort.writtenBytes().size)

            val framedPort = FakeSerialPort()
            framedSession.start(framedPort, TEST_UNO, SensorProtocol.FRAMED, 115_200)
            val link = SessionStimulatorLink(framedSession)
            assertNotNull(link.send(params))
            assertNotNull(link.stimulate(stimulus))
            // One encoder per link: the stimulus is the next sequence number.
            val expected = ByteArray(2 * FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
            val encoder = FramedEncoder()
            var length = encoder.setGrains(params, expected)
            length += encoder.stimulate(stimulus, expected, length)
            assertArrayEquals(expected.copyOf(length), framedPort.writtenBytes())
            assertNull(SessionStimulatorLink(csvSession).stimulate(stimulus))
        } finally {
            csvSession.disconnect()
            framedSession.disconnect()
        }
    }

    @Test
    fun screen_atTheCap_disablesStrongerAndSaysSo() {
        val state = ElectrotactileUiState.Electrode(4, 200, 2.7, atCap = true, steps = listOf(70, 65, 80, 75, 200, 60, 60, 60, 60), boardReady = false, message = null)
        compose.setContent { ElectrotactileCalibrationScreen(state, ElectrotactileActions()) }

        compose.onNodeWithText("Not yet: stronger").assertIsNotEnabled()
        compose.onNodeWithText("Give stimulus").assertIsNotEnabled()
        compose.onNodeWithText("Too strong").assertIsEnabled()
        compose.onNodeWithText("At the 2.7 mA cap: it cannot go higher.").assertExists()
        compose.onNodeWithText("Next stimulus: 2.700 mA, step 200 of 200, 200 ms").assertExists()
        compose.onNodeWithContentDescription("Electrode 1: 0.945 mA").assertExists()
        compose.onNodeWithContentDescription("Electrode 6: not yet calibrated").assertExists()
    }

    @Test
    fun boardRefusesTheStimulus_theScreenShowsTheFirmwaresReasonAsAnError() {
        val link = TestStimulatorLink(ready = true)
        val viewModel = ElectrotactileCalibrationViewModel(link)
        viewModel.giveStimulus()
        assertEquals("Gave 200 ms at 0.810 mA on electrode 1: how did it feel?", viewModel.state().message)
        assertFalse(viewModel.state().problem)

        link.handles.single().answer(CommandState.Rejected(AckStatus.OUT_OF_RANGE, 5, "an amplitude step past 200 (2.7 mA)"))

        val refused = viewModel.state()
        assertEquals("The board refused the 200 ms stimulus on electrode 1: an amplitude step past 200 (2.7 mA)", refused.message)
        assertTrue(refused.problem)
        compose.setContent { ElectrotactileCalibrationScreen(refused, ElectrotactileActions()) }
        compose.onNodeWithText("The board refused the 200 ms stimulus on electrode 1: an amplitude step past 200 (2.7 mA)").assertExists()
    }

    @Test
    fun wholeArrayCheckUnanswered_isNotSentAnyMore_andSaysSo_anAcknowledgedOneStaysSent() {
        val link = TestStimulatorLink(ready = true)
        val viewModel = ElectrotactileCalibrationViewModel(link)
        repeat(9) { viewModel.clearAndPainFree() }
        viewModel.sendWholeArrayCheck()
        link.handles.last().answer(CommandState.Acknowledged)
        assertTrue((viewModel.state() as ElectrotactileUiState.WholeArrayCheck).sent)
        assertEquals("Sent: press the sensor and feel the grains", viewModel.state().message)

        viewModel.sendWholeArrayCheck()
        link.handles.last().answer(CommandState.TimedOut("no acknowledgement within 500 ms"))

        val unanswered = viewModel.state() as ElectrotactileUiState.WholeArrayCheck
        assertFalse(unanswered.sent)
        assertTrue(unanswered.problem)
        assertEquals("No answer from the board to the grain settings (39 grains on 9 electrodes): no acknowledgement within 500 ms", unanswered.message)
    }
}
