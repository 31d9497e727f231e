package org.hapticon.core.pattern

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Test

class PatternVibrationTest {
    // Ramp up 100 ms, hold 200 ms, down 100 ms; the carrier sweeps 100 → 200 Hz.
    private val swell = HapticPattern(
        "swell",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.1, 1.0), AmplitudeKey(0.3, 1.0), AmplitudeKey(0.4, 0.0)),
        listOf(FrequencyKey(0.0, 100.0), FrequencyKey(0.4, 200.0)),
    )
    private val info = EnvelopeEffectInfo.GUARANTEED

    @Test
    fun of_wideFrequencyProfile_waveformPointsAtThePatternsOwnHertz() {
        val envelope = PatternEnvelope.of(swell, info, 50.0..300.0) as PatternEnvelope.Waveform
        assertEquals(100.0, envelope.initialHz, 1e-9)
        assertEquals(3, envelope.points.size)
        val expected = listOf(Triple(1.0, 125.0, 100L), Triple(1.0, 175.0, 200L), Triple(0.0, 200.0, 100L))
        envelope.points.zip(expected).forEach { (point, want) ->
            assertEquals(want.first, point.amplitude, 1e-9)
            assertEquals(want.second, point.hertz, 1e-9)
            assertEquals(want.third, point.millis)
        }
        assertEquals(0, envelope.pitch.octaves)
        assertEquals(400L, envelope.totalMillis)
        assertEquals(0.0, envelope.fidelity.rmsError, 1e-3)
    }

    @Test
    fun of_narrowFrequencyProfile_clampsIntoTheRangeAndSaysSo() {
        val envelope = PatternEnvelope.of(swell, info, 150.0..250.0) as PatternEnvelope.Waveform
        assertEquals(150.0, envelope.initialHz, 1e-9)
        // The keys are clamped (100 → 150 Hz) and the curve runs straight between them: 150 → 200 Hz over 0.4 s.
        assertEquals(listOf(162.5, 187.5, 200.0), envelope.points.map { it.hertz })
        assertEquals("clamped to 150–250 Hz", envelope.pitch.summary)
    }

    @Test
    fun of_highNoteNarrowLowProfile_movesByOctaves() {
        val stroke = HapticIcon.STROKE.toPattern() // 349.2 Hz
        val envelope = PatternEnvelope.of(stroke, info, 120.0..240.0) as PatternEnvelope.Waveform
        assertEquals(-1, envelope.pitch.octaves)
        envelope.points.forEach { assertEquals(HapticIcon.STROKE.frequency / 2, it.hertz, 1e-9) }
    }

    @Test
    fun of_noFrequencyProfile_basicEnvelopeWithSharpnessFromTheFrequency() {
        val envelope = PatternEnvelope.of(swell, info, null) as PatternEnvelope.Basic
        val mapping = FrequencyMapping.DEFAULT
        assertEquals(mapping.normalizedOf(100.0), envelope.initialSharpness, 1e-12)
        assertEquals(listOf(125.0, 175.0, 200.0).map(mapping::normalizedOf), envelope.points.map { it.sharpness })
        assertEquals(listOf(1.0, 1.0, 0.0), envelope.points.map { Math.round(it.intensity * 1e9) / 1e9 })
        assertEquals(listOf(100L, 200L, 100L), envelope.points.map { it.millis })
    }

    @Test
    fun of_rampLongerThanTheMaximum_cutIntoEqualPartsOnTheSameLine() {
        val long = HapticPattern(
            "long",
            listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.5, 1.0), AmplitudeKey(2.5, 1.0), AmplitudeKey(3.0, 0.0)),
            listOf(FrequencyKey(0.0, 150.0)),
        )
        val envelope = PatternEnvelope.of(long, info, 100.0..200.0) as PatternEnvelope.Waveform
        assertEquals(listOf(500L, 1000L, 1000L, 500L), envelope.points.map { it.millis })
        assertEquals(listOf(1.0, 1.0, 1.0, 0.0), envelope.points.map { Math.round(it.amplitude * 1e9) / 1e9 })
        assertEquals(0.0, envelope.points.last().amplitude, 0.0)
    }

    @Test
    fun of_fadeCutIntoThirds_lastPointIsExactlyZero() {
        // 0.7 + (0 − 0.7)·3/3 is 1.1e-16 in doubles; Android's BasicEnvelopeBuilder throws unless the last intensity is 0.
        val fade = HapticPattern(
            "fade",
            listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.1, 0.7), AmplitudeKey(0.4, 0.7), AmplitudeKey(0.7, 0.0)),
            listOf(FrequencyKey(0.0, 150.0)),
        )
        val envelope = PatternEnvelope.of(fade, EnvelopeEffectInfo(16, 20, 100, 1600), null) as PatternEnvelope.Basic
        assertEquals(List(7) { 100L }, envelope.points.map { it.millis })
        assertEquals(0.0, envelope.points.last().intensity, 0.0)
        assertEquals(0.7, envelope.points[3].intensity, 0.0)
    }

    @Test
    fun of_tooFewPointsAfterCutting_refitsWithinTheBudgetOrGivesUp() {
        val long = HapticPattern(
            "long",
            listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.5, 1.0), AmplitudeKey(2.5, 1.0), AmplitudeKey(3.0, 0.0)),
            listOf(FrequencyKey(0.0, 150.0)),
        )
        val envelope = PatternEnvelope.of(long, info.copy(maxControlPoints = 3), 100.0..200.0)
        // Three points cannot hold a 2 s hold in 1 s ramps and both slopes within the error bound.
        assertNull(envelope)
    }

    @Test
    fun of_longerThanTheEffectMaximum_null() {
        val twentySeconds = HapticPattern("long", listOf(AmplitudeKey(0.0, 0.5), AmplitudeKey(20.0, 0.5)), listOf(FrequencyKey(0.0, 150.0)))
        assertNull(PatternEnvelope.of(twentySeconds, info, 100.0..200.0))
    }

    @Test
    fun of_knockPulsesShorterThanAControlPoint_nullSoTheWaveformPlays() {
        assertNull(PatternEnvelope.of(HapticIcon.KNOCK.toPattern(), info, 100.0..300.0))
    }

    @Test
    fun of_brokenInfoOrRange_nullOrBasic() {
        assertNull(PatternEnvelope.of(swell, info.copy(maxControlPoints = 0), 50.0..300.0))
        assertNull(PatternEnvelope.of(swell, info.copy(minControlPointMillis = 0), 50.0..300.0))
        // A NaN or empty profile range counts as no profile: the basic builder, never a NaN frequency.
        assertTrue(PatternEnvelope.of(swell, info, Double.NaN..300.0) is PatternEnvelope.Basic)
        assertTrue(PatternEnvelope.of(swell, info, 200.0..200.0) is PatternEnvelope.Basic)
    }

    @Test
    fun vibrationWaveform_constantHalf_oneStepAt128() {
        val half = HapticPattern("half", listOf(AmplitudeKey(0.0, 0.5), AmplitudeKey(0.05, 0.5)), listOf(FrequencyKey(0.0, 150.0)))
        val waveform = half.vibrationWaveform()
        assertArrayEquals(longArrayOf(50), waveform.timings())
        assertArrayEquals(intArrayOf(128), waveform.amplitudes()) // 0.5 · 255 = 127.5, ties up
    }

    @Test
    fun driveEnvelope_transientAddsItsHannWindowCappedAtOne() {
        val tap = HapticPattern("tap", emptyList(), listOf(FrequencyKey(0.0, 150.0)), listOf(Transient(0.0, 0.5, 0.5)))
        val envelope = tap.driveEnvelope()
        assertEquals(0.25, envelope(Transient.DURATION_SECONDS / 2), 1e-12) // peak intensity² at the window's middle
        assertEquals(0.0, envelope(0.0), 1e-12)
        val loud = HapticPattern("loud", listOf(AmplitudeKey(0.0, 0.9), AmplitudeKey(0.1, 0.9)), listOf(FrequencyKey(0.0, 150.0)),
            listOf(Transient(0.0, 1.0, 0.5)))
        assertEquals(1.0, loud.driveEnvelope()(0.01), 0.0)
    }
}
