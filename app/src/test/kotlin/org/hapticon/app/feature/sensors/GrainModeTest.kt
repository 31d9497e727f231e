package org.hapticon.app.feature.sensors

import android.content.Context
import org.hapticon.app.playback.lastUsage
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.app.playback.usageVibrator
import android.os.Vibrator
import androidx.test.core.app.ApplicationProvider
import java.util.Locale
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
import org.hapticon.testing.TEST_UNO
import org.hapticon.testing.TestUsbDevices
import org.hapticon.sensor.glove.SessionGloveSource
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.ForceInput
import org.hapticon.sensor.grains.GrainEngine
import org.hapticon.sensor.live.SensorSession
import org.hapticon.testing.FakeSerialPort
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

/**
 * The FSR grain mode end to end: a scripted force stream from a fake board, through the session, the
 * grain engine and sensor-bridge's GrainDecider, to what the (Robolectric) vibrator was handed.
 */
@OptIn(ExperimentalCoroutinesApi::class)
@RunWith(RobolectricTestRunner::class)
class GrainModeTest {
    private val dispatcher = StandardTestDispatcher()
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val vibrator: Vibrator = defaultVibrator(context)
    private val output = RecordingVibrationOutput(VibratorVibrationOutput(usageVibrator(vibrator))) { lastVibration(vibrator) }
    private val usb = TestUsbDevices()
    private val session = SensorSession(usb)
    private val grains = GrainEngine(output).also { session.addFrameListener(it) }
    private lateinit var viewModel: SensorsViewModel

    @Before
    fun setUp() {
        Dispatchers.setMain(dispatcher)
        shadowOf(vibrator).setHasAmplitudeControl(true)
        viewModel = SensorsViewModel(usb, session, grains, SessionGloveSource(session))
    }

    @After
    fun tearDown() {
        session.disconnect()
        Dispatchers.resetMain()
    }

    /** A CSV board sending one `force` column in newtons at 100 Hz (the mode's default rate for CSV). */
    private fun TestScope.play(forces: List<Double>): SensorsUiState.Ready {
        backgroundScope.launch { viewModel.uiState.collect {} }
        val csv = "force\n" + forces.joinToString("") { "%.2f\n".format(Locale.ROOT, it) }
        usb.ports[TEST_UNO.id] = FakeSerialPort().enqueue(csv.toByteArray(), chunkSize = 64).enqueueEnd()
        viewModel.setGrainsEnabled(true)
        viewModel.setForceInput(ForceInput.NEWTONS)
        viewModel.setGrainCount(10) // 10 linear bins over 0–10 N: an edge every newton
        viewModel.setDistribution(BinDistribution.LINEAR)
        viewModel.setGrainAmplitude(200)
        runCurrent()
        viewModel.connect()
        runCurrent()
        assertTrue(session.awaitStopped(5_000))
        advanceTimeBy(100)
        runCurrent()
        return viewModel.uiState.value as SensorsUiState.Ready
    }

    @Test
    fun forceRamp_playsOneTwentyMillisecondBurstPerNewtonCrossed() = runTest(dispatcher) {
        // 0 → 4.5 N in 0.05 N steps (0.9 s), then held: the filtered force crosses 1, 2, 3 and 4 N.
        val ramp = (0..90).map { it * 0.05 } + List(20) { 4.5 }

        val state = play(ramp)

        val burst = RecordedVibration(timings = listOf(20L), amplitudes = listOf(200))
        assertEquals(List(4) { burst }, output.played.toList())
        assertEquals(burst, lastVibration(vibrator))
        // A grain emulates the material under the finger: PHYSICAL_EMULATION, which Android plays in the background too.
        assertEquals(VibrationUsage.PHYSICAL_EMULATION, lastUsage(vibrator))
        assertEquals(4L, state.grains.grainsPlayed)
        assertEquals(100.0, grains.status.value.sampleRateHz!!, 0.0)
    }

    @Test
    fun forceStep_noNewGrainWhileOnePlays() = runTest(dispatcher) {
        // 0 → 9.5 N at once. Low-passed (20 Hz at 100 Hz) the force passes bins 6, 8, 9 in three samples,
        // but a 20 ms grain lasts 2 samples: bin 6 fires, bin 8 comes while it plays, bin 9 fires after it.
        val step = listOf(0.0) + List(30) { 9.5 }

        val state = play(step)

        assertEquals(2, output.played.size)
        assertEquals(2L, state.grains.grainsPlayed)
        assertEquals(RecordedVibration(listOf(20L), listOf(200)), lastVibration(vibrator))
    }

    @Test
    fun grainModeOff_playsNothing() = runTest(dispatcher) {
        backgroundScope.launch { viewModel.uiState.collect {} }
        usb.ports[TEST_UNO.id] = FakeSerialPort().enqueue("force\n0\n5\n9\n0\n".toByteArray()).enqueueEnd()
        runCurrent()

        viewModel.connect()
        runCurrent()
        assertTrue(session.awaitStopped(5_000))

        assertEquals(0, output.played.size)
    }
}
