package org.hapticon.app.feature.glove

import android.content.Context
import org.hapticon.app.playback.lastUsage
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.app.playback.usageVibrator
import android.os.Vibrator
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.ExperimentalCoroutinesApi
import kotlinx.coroutines.launch
import kotlinx.coroutines.test.StandardTestDispatcher
import kotlinx.coroutines.test.TestScope
import kotlinx.coroutines.test.advanceTimeBy
import kotlinx.coroutines.test.resetMain
import kotlinx.coroutines.test.runCurrent
import kotlinx.coroutines.test.runTest
import kotlinx.coroutines.test.setMain
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.VibratorVibrationOutput
import org.hapticon.app.playback.defaultVibrator
import org.hapticon.app.playback.lastVibration
import org.hapticon.app.sensors.RecordingVibrationOutput
import org.hapticon.app.sensors.SavedCalibration
import org.hapticon.app.sensors.TestCalibrationStore
import org.hapticon.app.sensors.TestClock
import org.hapticon.app.sensors.TestGloveSource
import org.hapticon.app.sensors.TestHandshakeLink
import org.hapticon.messaging.HandPose
import org.hapticon.app.sensors.TestPartnerHand
import org.hapticon.sensor.glove.FlexCalibration
import org.hapticon.sensor.glove.GloveFinger
import org.hapticon.sensor.glove.HandRegion
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class HandshakeViewModelTest {
    private val dispatcher = StandardTestDispatcher()
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val vibrator: Vibrator = defaultVibrator(context)
    private val output = RecordingVibrationOutput(VibratorVibrationOutput(usageVibrator(vibrator))) { lastVibration(vibrator) }
    private val glove = TestGloveSource()
    private val store = TestCalibrationStore()
    private val partner = TestPartnerHand(thumbDegrees = 0.0, middleDegrees = 67.95)
    private val clock = TestClock()
    private val link = TestHandshakeLink()
    private lateinit var viewModel: HandshakeViewModel

    @Before
    fun setUp() {
        Dispatchers.setMain(dispatcher)
        shadowOf(vibrator).setHasAmplitudeControl(true)
        viewModel = HandshakeViewModel(glove, store, output, simulatedPartner = partner, clock = clock, link = link)
    }

    @After
    fun tearDown() = Dispatchers.resetMain()

    private fun TestScope.grip(thumbDegrees: Double, middleDegrees: Double, thumb: FlexCalibration = FlexCalibration.THUMB_DEFAULT) {
        glove.push(glove.voltsAt(thumbDegrees, thumb), glove.voltsAt(middleDegrees, FlexCalibration.MIDDLE_DEFAULT))
        advanceTimeBy(40)
        runCurrent()
    }

    private val ready get() = viewModel.uiState.value as HandshakeUiState.Ready

    @Test
    fun simulatedPartner_gripGivesTheDocumentedPressuresAndVibratesAtTheLargestRegionAmplitude() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        viewModel.setSimulatedPartner(true)
        runCurrent()

        // docs/sensor-models.md's worked example: self 50°/105°, partner 0°/67.95°.
        grip(50.0, 105.0)

        val state = ready
        assertTrue(state.active)
        assertEquals(50.0, state.selfThumbDegrees, 1e-9)
        assertEquals(105.0, state.selfMiddleDegrees, 1e-9)
        assertEquals(67.95, state.partnerMiddleDegrees, 0.0)
        assertEquals(2.19145, state.regions[HandRegion.PALM.ordinal].pressureVolts, 1e-9)
        assertEquals(1.9714, state.regions[HandRegion.THUMB.ordinal].pressureVolts, 1e-9)
        // Middle: n = 0.66 → 40 + 215·0.66 = 181.9 → 182, the largest of the six regions.
        assertEquals(182, state.phoneAmplitude)
        assertEquals(listOf(RecordedVibration(listOf(250L), listOf(182))), output.played.toList())
        // The partner's grip emulated on the vibrator.
        assertEquals(VibrationUsage.PHYSICAL_EMULATION, lastUsage(vibrator))
    }

    @Test
    fun amplitudeUpdates_areRateLimitedAndStopWhenTheHandshakeEnds() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        viewModel.setSimulatedPartner(true)
        runCurrent()
        grip(50.0, 105.0)

        // 10 ms later the partner squeezes harder: too soon for another vibrator call.
        clock.advanceMillis(10)
        partner.middleDegrees = 105.0
        grip(50.0, 105.0)
        assertEquals(1, output.played.size)

        // 50 ms after the first call the new level goes out.
        clock.advanceMillis(40)
        grip(50.0, 105.0)
        assertEquals(2, output.played.size)
        assertTrue(output.played.last()!!.amplitudes.single() > 182)

        // Both hands open: the vibrator stops at once.
        clock.advanceMillis(1)
        partner.middleDegrees = 0.0
        grip(0.0, 0.0)
        assertFalse(ready.active)
        assertEquals(0, ready.phoneAmplitude)
        assertEquals(1, output.stops)
        assertTrue(shadowOf(vibrator).isCancelled)
    }

    @Test
    fun noPartner_isAnOpenHandAndOwnGripStillStartsTheHandshake() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        runCurrent()

        grip(50.0, 40.0)

        assertFalse(ready.simulatedPartner)
        assertEquals(0.0, ready.partnerMiddleDegrees, 0.0)
        assertTrue(ready.active)
    }

    @Test
    fun usersSavedCalibration_turnsVoltagesIntoAngles() = runTest(dispatcher) {
        val mine = FlexCalibration(0.02, 14.0)
        store.save(store.currentUser.value, GloveFinger.THUMB, SavedCalibration(mine, 0.999, 0.5, 0))
        backgroundScope.launch { viewModel.uiState.collect {} }
        runCurrent()

        grip(40.0, 0.0, thumb = mine)

        assertEquals(40.0, ready.selfThumbDegrees, 1e-9)
        assertTrue(ready.thumbCalibrated)
        assertFalse(ready.middleCalibrated)
    }

    @Test
    fun vibrationOff_neverVibrates() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        viewModel.setSimulatedPartner(true)
        viewModel.setVibration(false)
        runCurrent()

        grip(50.0, 105.0)

        assertTrue(ready.active)
        assertTrue(output.played.isEmpty())
    }

    @Test
    fun faultySensor_countsAsOpen() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        runCurrent()

        glove.push(Double.NaN, glove.divider.supplyVolts)
        advanceTimeBy(40)
        runCurrent()

        assertTrue(ready.thumbFault)
        assertTrue(ready.middleFault)
        assertEquals(0.0, ready.selfMiddleDegrees, 0.0)
        assertFalse(ready.active)
    }

    @Test
    fun lucidGlovesGlove_getsTheFingerServoValuesRateLimitedAndReleasedWhenTheHandshakeEnds() = runTest(dispatcher) {
        glove.acceptsForceFeedbackFlow.value = true
        backgroundScope.launch { viewModel.uiState.collect {} }
        viewModel.setSimulatedPartner(true)
        runCurrent()

        grip(50.0, 105.0)
        val first = glove.forceFeedbackSent.single()
        assertEquals(SERVOS_AT_WORKED_EXAMPLE, first)
        assertEquals(first, ready.servoValues)

        // The partner squeezes harder 10 ms later: too soon; 50 ms after the first command it goes out.
        clock.advanceMillis(10)
        partner.middleDegrees = 105.0
        grip(50.0, 105.0)
        assertEquals(1, glove.forceFeedbackSent.size)
        clock.advanceMillis(40)
        grip(50.0, 105.0)
        assertEquals(2, glove.forceFeedbackSent.size)
        assertTrue(glove.forceFeedbackSent[1].zip(first).all { (harder, before) -> harder >= before })

        // Both hands open 1 ms later: released at once.
        clock.advanceMillis(1)
        partner.middleDegrees = 0.0
        grip(0.0, 0.0)
        assertEquals(listOf(0, 0, 0, 0, 0), glove.forceFeedbackSent.last())
        assertEquals(3L, ready.forceFeedbackCommands)
        assertTrue(ready.forceFeedbackAvailable)
    }

    @Test
    fun forceFeedbackOff_releasesTheGloveAndSendsNoMore() = runTest(dispatcher) {
        glove.acceptsForceFeedbackFlow.value = true
        backgroundScope.launch { viewModel.uiState.collect {} }
        viewModel.setSimulatedPartner(true)
        runCurrent()
        grip(50.0, 105.0)

        viewModel.setForceFeedback(false)
        clock.advanceMillis(100)
        grip(60.0, 105.0)

        assertEquals(listOf(SERVOS_AT_WORKED_EXAMPLE, listOf(0, 0, 0, 0, 0)), glove.forceFeedbackSent.toList())
        assertEquals("Force feedback off: the glove's servos are released.", forceFeedbackStatus(ready))
    }

    @Test
    fun gloveWithoutForceFeedback_getsNothingAndTheScreenSaysWhy() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        viewModel.setSimulatedPartner(true)
        runCurrent()

        grip(50.0, 105.0)

        assertTrue(ready.active)
        assertTrue(glove.forceFeedbackSent.isEmpty())
        assertEquals(0L, ready.forceFeedbackCommands)
        assertEquals("Force feedback needs a LucidGloves glove streaming on the Sensors screen.", forceFeedbackStatus(ready))
    }

    @Test
    fun networkPartner_theirArrivingHandDrivesThePressureAndOursGoesOutAt30PerSecond() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        runCurrent()
        assertEquals(listOf("bob"), ready.peers)

        viewModel.setNetworkPartner("bob")
        // Bob's hand arrives: the worked example's partner, 0° / 67.95°.
        link.partner("bob").offer(HandPose("bob", 0.0, 67.95, 1), clock.nanos)
        grip(50.0, 105.0)

        assertEquals("bob", ready.networkPeer)
        assertTrue(ready.networkPartnerLive)
        assertEquals(1.9714, ready.regions[HandRegion.THUMB.ordinal].pressureVolts, 1e-9)
        assertEquals(listOf(Triple("bob", 50.0, 105.0)), link.sent.map { Triple(it.first, Math.round(it.second * 1e6) / 1e6, Math.round(it.third * 1e6) / 1e6) })

        // 10 ms later: too soon for another sample; 33 ms after the first, the next goes out.
        clock.advanceMillis(10)
        grip(50.0, 105.0)
        assertEquals(1, link.sent.size)
        clock.advanceMillis(23)
        grip(50.0, 105.0)
        assertEquals(2, link.sent.size)

        // Bob goes quiet for more than half a second: his hand opens, and so does the handshake on his side.
        clock.advanceMillis(600)
        grip(0.0, 0.0)
        assertFalse(ready.networkPartnerLive)
        assertEquals(0.0, ready.partnerMiddleDegrees, 0.0)
        assertFalse(ready.active)
    }

    @Test
    fun networkPartnerOff_stopsSending() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        runCurrent()
        viewModel.setNetworkPartner("bob")
        grip(10.0, 10.0)
        viewModel.setNetworkPartner(null)
        clock.advanceMillis(100)
        grip(10.0, 10.0)

        assertEquals(1, link.sent.size)
        assertEquals(null, ready.networkPeer)
    }

    private companion object {
        /** docs/sensor-models.md's worked example (self 50°/105°, partner 0°/67.95°), thumb … pinky: the thumb's n = 0.635 of its travel. */
        val SERVOS_AT_WORKED_EXAMPLE = listOf(635, 600, 660, 595, 585)
    }
}
