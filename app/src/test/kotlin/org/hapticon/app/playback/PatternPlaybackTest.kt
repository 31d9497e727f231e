package org.hapticon.app.playback

import android.content.Context
import android.os.Build
import android.os.Vibrator
import androidx.test.core.app.ApplicationProvider
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.FrequencyMapping
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternEnvelope
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.pattern.toPattern
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

/**
 * Patterns on the vibrator. Robolectric's runtime here is API 35, so the step waveforms are asserted as the shadow
 * vibrator received them; the API 36 envelope is asserted as the control points [PatternPlan] hands to the builder,
 * for phones with no, a narrow and a wide frequency profile.
 */
@RunWith(RobolectricTestRunner::class)
class PatternPlaybackTest {
    private lateinit var vibrator: Vibrator
    private var device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
    private var override: RendererKind? = null
    private lateinit var player: AdaptiveHapticPlayer

    // Up to full in 20 ms, held 20 ms, then silence; the carrier sweeps 100 → 200 Hz.
    private val ramp = HapticPattern(
        "ramp",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.02, 1.0), AmplitudeKey(0.04, 1.0)),
        listOf(FrequencyKey(0.0, 100.0), FrequencyKey(0.04, 200.0)),
    )

    // Ramp up 100 ms, hold 200 ms, down 100 ms; 100 → 200 Hz.
    private val swell = HapticPattern(
        "swell",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.1, 1.0), AmplitudeKey(0.3, 1.0), AmplitudeKey(0.4, 0.0)),
        listOf(FrequencyKey(0.0, 100.0), FrequencyKey(0.4, 200.0)),
    )
    private val envelopePhone = DeviceCapabilities(
        hasVibrator = true, hasAmplitudeControl = true, apiLevel = 36, envelopeEffectsSupported = true,
        envelopeInfo = EnvelopeEffectInfo.GUARANTEED,
    )

    @Before
    fun setUp() {
        val context = ApplicationProvider.getApplicationContext<Context>()
        vibrator = context.getSystemService(Vibrator::class.java)
        shadowOf(vibrator).setHasAmplitudeControl(true)
        player = AdaptiveHapticPlayer(usageVibrator(vibrator), device = { device }, override = { override })
    }

    @Test
    fun play_amplitudeControlBelowApi36_exactStepsOfTheDriveEnvelope() {
        val playback = player.play(ramp, VibrationUsage.TOUCH) as Playback.Playing
        // 10 ms steps: the rising ramp averages 0.25 then 0.75 (→ 64, 191 of 255), the hold is full.
        assertEquals(RecordedVibration(listOf(10L, 10L, 20L), listOf(64, 191, 255)), lastVibration(vibrator))
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, playback.renderer)
        assertEquals(40L, playback.durationMillis)
    }

    @Test
    fun play_noAmplitudeControl_onOffAtHalfThePeak() {
        device = device.copy(hasAmplitudeControl = false)
        val playback = player.play(ramp, VibrationUsage.TOUCH) as Playback.Playing
        assertEquals(RecordedVibration(listOf(10L, 30L), listOf(0, 255)), lastVibration(vibrator))
        assertEquals(RendererKind.ON_OFF, playback.renderer)
    }

    @Test
    fun play_overrideOnOff_honouredOnAnAmplitudePhone() {
        override = RendererKind.ON_OFF
        assertEquals(RendererKind.ON_OFF, (player.play(ramp, VibrationUsage.TOUCH) as Playback.Playing).renderer)
        assertEquals(listOf(0, 255), lastVibration(vibrator)!!.amplitudes)
    }

    @Test
    fun play_noVibrator_unsupportedAndNothingSent() {
        device = device.copy(hasVibrator = false)
        assertEquals(Playback.Unsupported, player.play(ramp, VibrationUsage.TOUCH))
        assertNull(lastVibration(vibrator))
    }

    @Test
    fun play_envelopePlanOnAnOlderPlatform_fallsBackToTheExactSteps() {
        // Only made-up capabilities can claim 36 on this runtime; the platform's own level decides.
        assertEquals(35, Build.VERSION.SDK_INT)
        device = envelopePhone.copy(frequencyRangeHz = 50.0..300.0)
        assertTrue(player.planFor(swell) is PatternPlan.Envelope)
        player.play(ramp, VibrationUsage.TOUCH)
        assertEquals(RecordedVibration(listOf(10L, 10L, 20L), listOf(64, 191, 255)), lastVibration(vibrator))
    }

    @Test
    fun plan_wideFrequencyProfile_waveformBuilderPointsInHz() {
        device = envelopePhone.copy(frequencyRangeHz = 50.0..300.0)
        val envelope = (player.planFor(swell) as PatternPlan.Envelope).envelope as PatternEnvelope.Waveform
        assertEquals(100.0, envelope.initialHz, 1e-9)
        assertEquals(listOf(100L, 200L, 100L), envelope.points.map { it.millis })
        assertEquals(listOf(125.0, 175.0, 200.0), envelope.points.map { Math.round(it.hertz * 1e6) / 1e6 })
        assertEquals(listOf(1.0, 1.0, 0.0), envelope.points.map { Math.round(it.amplitude * 1e6) / 1e6 })
        assertEquals("plays at its own pitch; 50–300 Hz covers it", envelope.pitch.summary)
    }

    @Test
    fun plan_narrowFrequencyProfile_octaveShiftOrClampAsChosen() {
        device = envelopePhone.copy(frequencyRangeHz = 120.0..240.0)
        val stroke = HapticIcon.STROKE.toPattern()
        val octaves = (player.planFor(stroke) as PatternPlan.Envelope).envelope as PatternEnvelope.Waveform
        octaves.points.forEach { assertEquals(HapticIcon.STROKE.frequency / 2, it.hertz, 1e-9) }
        val clamped = AdaptiveHapticPlayer(usageVibrator(vibrator), { device }, { null }, pitchFit = { PitchFit.CLAMP })
        val clampedEnvelope = (clamped.planFor(stroke) as PatternPlan.Envelope).envelope as PatternEnvelope.Waveform
        clampedEnvelope.points.forEach { assertEquals(240.0, it.hertz, 0.0) }
        assertEquals("clamped to 120–240 Hz", clampedEnvelope.pitch.summary)
    }

    @Test
    fun plan_noFrequencyProfile_basicBuilderWithSharpnessFromTheFrequency() {
        device = envelopePhone
        val envelope = (player.planFor(swell) as PatternPlan.Envelope).envelope as PatternEnvelope.Basic
        val mapping = FrequencyMapping.DEFAULT
        assertEquals(mapping.normalizedOf(100.0), envelope.initialSharpness, 1e-12)
        assertEquals(listOf(125.0, 175.0, 200.0).map(mapping::normalizedOf), envelope.points.map { it.sharpness })
        assertEquals(0.0, envelope.points.last().intensity, 0.0) // ends on zero intensity, as the API asks
    }

    @Test
    fun plan_knockPulsesOnAnEnvelopePhone_stepsBecauseControlPointsCannotFollow() {
        device = envelopePhone.copy(frequencyRangeHz = 50.0..300.0)
        val plan = player.planFor(HapticIcon.KNOCK.toPattern())
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, plan.renderer)
    }

    @Test
    fun play_longestLoudestPattern_staysWithinTheVibrationLimits() {
        // The hardest pattern a file may hold: 4096 keys alternating silence and full drive over the 30 s cap.
        val keys = (0 until HapticPattern.MAX_KEYS).map { AmplitudeKey(it * 30.0 / (HapticPattern.MAX_KEYS - 1), (it % 2).toDouble()) }
        val hostile = HapticPattern("hostile", keys, listOf(FrequencyKey(0.0, 20_000.0)))
        player.play(hostile, VibrationUsage.TOUCH)
        val recorded = lastVibration(vibrator)!!
        assertEquals(30_000L, recorded.timings.sum())
        assertTrue(recorded.amplitudes.all { it in 0..255 })
        assertTrue(recorded.timings.all { it > 0 })
    }
}
