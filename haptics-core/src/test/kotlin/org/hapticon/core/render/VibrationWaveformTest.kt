package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.hapticon.core.render.RenderAssertions.assertRejected
import org.junit.Test
import kotlin.math.sqrt

class VibrationWaveformTest {
    /** The limits the app relies on when it hands the arrays to VibrationEffect. */
    private fun assertPlayable(waveform: VibrationWaveform, expectedMillis: Long) {
        val timings = waveform.timings()
        val amplitudes = waveform.amplitudes()
        assertEquals(timings.size, amplitudes.size)
        assertTrue(timings.isNotEmpty())
        assertTrue(timings.all { it > 0 })
        assertTrue(amplitudes.all { it in 0..255 })
        for (i in 1 until amplitudes.size) assertTrue(amplitudes[i] != amplitudes[i - 1])
        assertEquals(expectedMillis, timings.sum())
        assertEquals(expectedMillis, waveform.totalMillis)
    }

    @Test
    fun amplitudeSteps_knock_isThreeTwentyMillisecondPulses() {
        val waveform = VibrationWaveform.amplitudeSteps(HapticIcon.KNOCK, EnvelopeModel.PAPER)
        // Each pulse spans two 10 ms steps whose mean envelope is 0.375: round(0.375 · 255) = 96.
        assertArrayEquals(longArrayOf(20, 250, 20, 250, 20), waveform.timings())
        assertArrayEquals(intArrayOf(96, 0, 96, 0, 96), waveform.amplitudes())
        assertEquals(10, waveform.stepMillis)
        assertEquals(560L, waveform.totalMillis)
    }

    @Test
    fun amplitudeSteps_knock_fidelityMatchesTheAnalyticError() {
        val fidelity = VibrationWaveform.amplitudeSteps(HapticIcon.KNOCK, EnvelopeModel.PAPER).fidelity
        // Per pulse ∫(c − e)² = 2·(5c² − 2.5c + 5/12) + 10·(c − 0.5)² with c = 96/255 (ms · amplitude²).
        val c = 96.0 / 255
        val perPulse = 2 * (5 * c * c - 2.5 * c + 5.0 / 12) + 10 * (c - 0.5) * (c - 0.5)
        assertEquals(sqrt(3 * perPulse / 560), fidelity.rmsError, 1e-5)
        // Largest error at the first 0.1 ms cell of a pulse, where the envelope is 0.005.
        assertEquals(c - 0.005, fidelity.maxError, 1e-12)
        assertEquals(
            "amplitude steps of 10 ms, 5 entries; RMS error 0.0528 (39.5% of the envelope RMS), max error 0.3715",
            fidelity.description,
        )
    }

    @Test
    fun amplitudeSteps_hit_followsEachRampStepByStep() {
        val waveform = VibrationWaveform.amplitudeSteps(HapticIcon.HIT, EnvelopeModel.PAPER)
        // Attack step mean 0.5 → 128; hold → 255; release steps 5/6, 1/2, 1/6 → 213, 128, 43; 60 ms off.
        val pulseTimings = listOf(10L, 100, 10, 10, 10)
        val pulseAmplitudes = listOf(128, 255, 213, 128, 43)
        val timings = (1..7).flatMap { pulseTimings + 60L } + pulseTimings
        val amplitudes = (1..7).flatMap { pulseAmplitudes + 0 } + pulseAmplitudes
        assertArrayEquals(timings.toLongArray(), waveform.timings())
        assertArrayEquals(amplitudes.toIntArray(), waveform.amplitudes())
        assertEquals(1540L, waveform.totalMillis)
    }

    @Test
    fun amplitudeSteps_processingModel_changesTheShape() {
        val waveform = VibrationWaveform.amplitudeSteps(HapticIcon.KNOCK, EnvelopeModel.PROCESSING)
        // 0→1 over 5 ms, 1→0.5 over 10 ms, 0.5→0 over 5 ms: step means 0.6875 and 0.4375 (111.6 of 255) in
        // continuous time. Processing at 44.1 kHz carries the attack's half-sample overshoot into the sustain,
        // which then ends one sample (22.7 µs) early, pulling the second step's mean just below 111.5.
        assertArrayEquals(longArrayOf(10, 10, 250, 10, 10, 250, 10, 10), waveform.timings())
        assertArrayEquals(intArrayOf(175, 111, 0, 175, 111, 0, 175, 111), waveform.amplitudes())
    }

    @Test
    fun amplitudeSteps_hug_holdsLevelAndKeepsErrorWithinQuantisation() {
        val waveform = VibrationWaveform.amplitudeSteps(HapticIcon.HUG, EnvelopeModel.PAPER)
        assertPlayable(waveform, 3000)
        val timings = waveform.timings()
        val amplitudes = waveform.amplitudes()
        // The 1 s hold at 0.5 is one entry at round(127.5) = 128, starting at 1500 ms.
        val hold = amplitudes.indices.single { timings[it] == 1000L }
        assertEquals(128, amplitudes[hold])
        assertEquals(1500L, timings.take(hold).sum())
        // Worst case: half a 10 ms step of the 0.001/ms release slope plus half an amplitude step.
        assertTrue(waveform.fidelity.maxError <= 0.005 + 0.5 / 255)
        assertTrue(waveform.fidelity.rmsError < 0.0025)
    }

    @Test
    fun amplitudeSteps_everyPresetModelAndStep_isPlayable() {
        for (icon in HapticIcon.PRESETS) {
            for (model in EnvelopeModel.values()) {
                for (step in listOf(1, 3, 7, 10, 25, 1000)) {
                    assertPlayable(VibrationWaveform.amplitudeSteps(icon, model, step), Math.round(icon.duration * 1000))
                    assertPlayable(VibrationWaveform.onOff(icon, model, stepMillis = step), Math.round(icon.duration * 1000))
                }
            }
        }
    }

    @Test
    fun amplitudeSteps_stroke_hasPlayableRampsAtMostItsLevel() {
        val waveform = VibrationWaveform.amplitudeSteps(HapticIcon.STROKE, EnvelopeModel.PAPER)
        assertPlayable(waveform, 10_800)
        assertEquals(77, waveform.amplitudes().max()) // round(0.3 · 255 = 76.5)
        assertTrue(waveform.fidelity.rmsError < 0.002)
    }

    @Test
    fun amplitudeSteps_tooManyEntries_doublesTheStepUntilTheyFit() {
        val waveform = VibrationWaveform.amplitudeSteps(HapticIcon.HUG, EnvelopeModel.PAPER, maxEntries = 10)
        assertPlayable(waveform, 3000)
        assertTrue(waveform.size <= 10)
        assertTrue(VibrationWaveform.amplitudeSteps(HapticIcon.HUG, EnvelopeModel.PAPER, stepMillis = 160).size > 10)
        assertEquals(320, waveform.stepMillis) // 10 → 20 → … → 320 ms, the first to give at most 10 entries
        val coarser = VibrationWaveform.amplitudeSteps(HapticIcon.HUG, EnvelopeModel.PAPER, maxEntries = 1)
        assertArrayEquals(longArrayOf(3000), coarser.timings())
        assertEquals(3000, coarser.stepMillis)
    }

    @Test
    fun amplitudeSteps_outOfRangeEnvelope_isClampedToSafeAmplitudes() {
        val loud = VibrationWaveform.amplitudeSteps({ 2.0 }, 0.05)
        assertArrayEquals(longArrayOf(50), loud.timings())
        assertArrayEquals(intArrayOf(255), loud.amplitudes())
        val broken = VibrationWaveform.amplitudeSteps({ t -> if (t < 0.02) Double.NaN else -1.0 }, 0.05)
        assertArrayEquals(longArrayOf(50), broken.timings())
        assertArrayEquals(intArrayOf(0), broken.amplitudes())
    }

    @Test
    fun amplitudeSteps_amplitudeBelowHalfAStep_isOff() {
        assertArrayEquals(intArrayOf(0), VibrationWaveform.amplitudeSteps({ 0.9 / 510 }, 0.03).amplitudes())
        assertArrayEquals(intArrayOf(1), VibrationWaveform.amplitudeSteps({ 1.1 / 510 }, 0.03).amplitudes())
    }

    @Test
    fun amplitudeSteps_briefSpike_isNeverDropped() {
        // 1 ms at 0.003 in a 10 ms step: mean 0.0003 rounds to 0, but the vibrator must still fire.
        val waveform = VibrationWaveform.amplitudeSteps({ t -> if (t < 0.001) 0.003 else 0.0 }, 0.02)
        assertArrayEquals(longArrayOf(10, 10), waveform.timings())
        assertArrayEquals(intArrayOf(1, 0), waveform.amplitudes())
    }

    @Test
    fun amplitudeSteps_lastStep_isShortenedToTheDuration() {
        val waveform = VibrationWaveform.amplitudeSteps({ t -> if (t < 0.01) 1.0 else 0.5 }, 0.0234)
        assertArrayEquals(longArrayOf(10, 13), waveform.timings())
        assertArrayEquals(intArrayOf(255, 128), waveform.amplitudes())
    }

    @Test
    fun amplitudeSteps_durationLimits_areEnforced() {
        assertEquals(30_000L, VibrationWaveform.amplitudeSteps({ 0.5 }, 30.0).totalMillis)
        assertEquals(30_000L, VibrationWaveform.amplitudeSteps({ 0.5 }, 30.0004).totalMillis)
        assertRejected("duration 30.001 s exceeds the 30.0 s safety cap") { VibrationWaveform.amplitudeSteps({ 0.5 }, 30.001) }
        assertRejected("duration 4.0E-4 s rounds to 0 ms: nothing to play") { VibrationWaveform.amplitudeSteps({ 0.5 }, 0.0004) }
        assertRejected("duration must be finite and >= 0, was NaN") { VibrationWaveform.amplitudeSteps({ 0.5 }, Double.NaN) }
        assertRejected("duration must be finite and >= 0, was -1.0") { VibrationWaveform.amplitudeSteps({ 0.5 }, -1.0) }
    }

    @Test
    fun amplitudeSteps_invalidParameters_areRejected() {
        assertRejected("stepMillis must be >= 1, was 0") { VibrationWaveform.amplitudeSteps(HapticIcon.KNOCK, EnvelopeModel.PAPER, stepMillis = 0) }
        assertRejected("maxEntries must be >= 1, was 0") { VibrationWaveform.amplitudeSteps(HapticIcon.KNOCK, EnvelopeModel.PAPER, maxEntries = 0) }
        assertRejected("threshold must be in (0, 1], was 0.0") { VibrationWaveform.onOff(HapticIcon.KNOCK, EnvelopeModel.PAPER, threshold = 0.0) }
        assertRejected("threshold must be in (0, 1], was 1.5") { VibrationWaveform.onOff(HapticIcon.KNOCK, EnvelopeModel.PAPER, threshold = 1.5) }
    }

    @Test
    fun timings_returnsACopy() {
        val waveform = VibrationWaveform.amplitudeSteps(HapticIcon.KNOCK, EnvelopeModel.PAPER)
        waveform.timings()[0] = 99
        waveform.amplitudes()[0] = 999
        assertEquals(20L, waveform.timings()[0])
        assertEquals(96, waveform.amplitudes()[0])
    }

    @Test
    fun onOff_knock_isFullStrengthDuringEachPulse() {
        val waveform = VibrationWaveform.onOff(HapticIcon.KNOCK, EnvelopeModel.PAPER)
        assertArrayEquals(longArrayOf(20, 250, 20, 250, 20), waveform.timings())
        assertArrayEquals(intArrayOf(255, 0, 255, 0, 255), waveform.amplitudes())
    }

    @Test
    fun onOff_hug_isOnWhileAboveHalfItsPeak() {
        val waveform = VibrationWaveform.onOff(HapticIcon.HUG, EnvelopeModel.PAPER)
        // The envelope reaches 0.25 at 750 ms on the way up and at 2750 ms on the way down.
        assertArrayEquals(longArrayOf(750, 2000, 250), waveform.timings())
        assertArrayEquals(intArrayOf(0, 255, 0), waveform.amplitudes())
        // Off where the ideal is ≤ 0.25, on (1.0) where it is 0.25..0.5: errors up to 0.75.
        assertEquals(0.75, waveform.fidelity.maxError, 1e-4)
    }

    @Test
    fun onOff_hit_mergesAttackHoldAndUpperRelease() {
        val waveform = VibrationWaveform.onOff(HapticIcon.HIT, EnvelopeModel.PAPER)
        // Steps with mean ≥ 0.5: attack (0.5), hold, release 5/6 and 1/2 → 130 ms on, 70 ms off.
        val timings = (1..7).flatMap { listOf(130L, 70L) } + listOf(130L, 10L)
        assertArrayEquals(timings.toLongArray(), waveform.timings())
        assertArrayEquals(IntArray(16) { if (it % 2 == 0) 255 else 0 }, waveform.amplitudes())
    }

    @Test
    fun onOff_thresholdIsRelativeToThePeak() {
        // Stroke peaks at 0.3; an absolute threshold of 0.5 would never switch on.
        val waveform = VibrationWaveform.onOff(HapticIcon.STROKE, EnvelopeModel.PAPER, threshold = 0.5)
        assertArrayEquals(longArrayOf(500, 2000, 600, 2000, 600, 2000, 600, 2000, 500), waveform.timings())
    }

    @Test
    fun onOff_silentEnvelope_isOneOffEntry() {
        val waveform = VibrationWaveform.onOff({ 0.0 }, 0.1)
        assertArrayEquals(longArrayOf(100), waveform.timings())
        assertArrayEquals(intArrayOf(0), waveform.amplitudes())
        assertEquals(0.0, waveform.fidelity.rmsError, 0.0)
    }
}
