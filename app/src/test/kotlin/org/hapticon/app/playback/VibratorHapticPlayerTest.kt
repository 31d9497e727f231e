package org.hapticon.app.playback

import android.content.Context
import android.os.Vibrator
import androidx.test.core.app.ApplicationProvider
import org.hapticon.core.HapticIcon
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.RendererKind
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

@RunWith(RobolectricTestRunner::class)
class VibratorHapticPlayerTest {
    private lateinit var vibrator: Vibrator
    private lateinit var player: VibratorHapticPlayer

    @Before
    fun setUp() {
        val context = ApplicationProvider.getApplicationContext<Context>()
        player = VibratorHapticPlayer.create(context)
        vibrator = context.getSystemService(Vibrator::class.java)
    }

    @Test
    fun play_knockWithAmplitudeControl_handsExactStepWaveformToVibrator() {
        shadowOf(vibrator).setHasAmplitudeControl(true)

        val playback = player.play(HapticIcon.KNOCK, VibrationUsage.TOUCH)

        // Knock: three 20 ms pulses (0.005 + 0.01 + 0.005 s) every 270 ms at mean envelope 0.375 → 96/255.
        assertEquals(
            RecordedVibration(timings = listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), amplitudes = listOf(175, 111, 0, 175, 111, 0, 175, 111)),
            lastVibration(vibrator),
        )
        assertEquals(560L, (playback as Playback.Playing).durationMillis)
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, playback.renderer)
        assertTrue(shadowOf(vibrator).isVibrating)
    }

    @Test
    fun play_hugWithAmplitudeControl_rampsOverThreeSeconds() {
        shadowOf(vibrator).setHasAmplitudeControl(true)

        player.play(HapticIcon.HUG, VibrationUsage.TOUCH)

        val recorded = lastVibration(vibrator)!!
        assertEquals(3000L, recorded.timings.sum())
        // The processing hug (the default model) peaks at 1 at the end of its 1.5 s attack: the 10 ms step around it
        // averages 0.9967 → 254; its sustain then ramps down to 0.5 (0.5 · 255 = 127.5 → 128 where it ends).
        assertTrue(recorded.amplitudes.all { it in 0..255 })
        assertEquals(254, recorded.amplitudes.max())
    }

    @Test
    fun play_withoutAmplitudeControl_fallsBackToFullStrengthOnOff() {
        shadowOf(vibrator).setHasAmplitudeControl(false)

        val playback = player.play(HapticIcon.KNOCK, VibrationUsage.TOUCH)

        assertEquals(RendererKind.ON_OFF, (playback as Playback.Playing).renderer)
        assertEquals(
            // The processing knock (the default model) is above half its peak only in each pulse's first 10 ms step.
            RecordedVibration(timings = listOf(10L, 260L, 10L, 260L, 10L, 10L), amplitudes = listOf(255, 0, 255, 0, 255, 0)),
            lastVibration(vibrator),
        )
    }

    @Test
    fun play_withoutVibrator_isUnsupportedAndVibratesNothing() {
        shadowOf(vibrator).setHasVibrator(false)

        val playback = player.play(HapticIcon.STROKE, VibrationUsage.TOUCH)

        assertEquals(Playback.Unsupported, playback)
        assertNull(lastVibration(vibrator))
    }

    @Test
    fun stop_afterPlay_cancelsVibration() {
        shadowOf(vibrator).setHasAmplitudeControl(true)
        player.play(HapticIcon.STROKE, VibrationUsage.TOUCH)

        player.stop()

        assertTrue(shadowOf(vibrator).isCancelled)
    }
}
