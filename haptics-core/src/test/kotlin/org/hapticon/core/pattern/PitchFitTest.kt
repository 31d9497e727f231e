package org.hapticon.core.pattern

import org.hapticon.core.HapticIcon
import org.hapticon.core.midiNoteToHz
import org.junit.Assert.assertEquals
import org.junit.Assert.assertSame
import org.junit.Assert.assertThrows
import org.junit.Test

class PitchFitTest {
    private val stroke = HapticIcon.STROKE.toPattern() // note 65, 349.2 Hz

    @Test
    fun insideTheRange_isNotMoved() {
        val fitted = stroke.fitPitchInto(100.0, 400.0)
        assertSame(stroke, fitted.pattern)
        assertEquals(0, fitted.octaves)
        assertEquals("plays at its own pitch; 100–400 Hz covers it", fitted.summary)
    }

    @Test
    fun octaves_narrowLowRange_movesDownOneOctave() {
        val fitted = stroke.fitPitchInto(120.0, 240.0)
        assertEquals(-1, fitted.octaves)
        assertEquals(HapticIcon.STROKE.frequency / 2, fitted.pattern.frequency.single().hertz, 1e-9)
        assertEquals("plays 1 octave lower (349.2 → 174.6 Hz) to fit 120–240 Hz", fitted.summary)
        assertEquals(stroke.amplitude, fitted.pattern.amplitude)
    }

    @Test
    fun octaves_sweepWiderThanTheRange_shiftsThenClampsTheEnds() {
        val sweep = HapticPattern("sweep", listOf(AmplitudeKey(0.0, 0.5), AmplitudeKey(1.0, 0.5)),
            listOf(FrequencyKey(0.0, 400.0), FrequencyKey(0.5, 800.0), FrequencyKey(1.0, 1600.0)))
        val fitted = sweep.fitPitchInto(100.0, 300.0)
        assertEquals(-2, fitted.octaves) // centre √(400·1600) = 800 Hz, the range's √(100·300) ≈ 173 Hz: log2 ≈ −2.2
        assertEquals(listOf(100.0, 200.0, 300.0), fitted.pattern.frequency.map { it.hertz })
        assertEquals(1, fitted.clampedKeys)
        assertEquals("plays 2 octaves lower (400.0 → 100.0 Hz) to fit 100–300 Hz; 1 frequency key still clamped", fitted.summary)
    }

    @Test
    fun clamp_movesOnlyWhatIsOutside() {
        val fitted = stroke.fitPitchInto(120.0, 240.0, PitchFit.CLAMP)
        assertEquals(240.0, fitted.pattern.frequency.single().hertz, 0.0)
        assertEquals("clamped to 120–240 Hz", fitted.summary)
    }

    private fun note(n: Int) = HapticPattern("note $n", listOf(AmplitudeKey(0.0, 1.0), AmplitudeKey(0.1, 0.0)), listOf(FrequencyKey(0.0, midiNoteToHz(n.toDouble()))))

    private fun played(n: Int, minHz: Double, maxHz: Double, fit: PitchFit) = note(n).fitPitchInto(minHz, maxHz, fit).pattern.frequency.single().hertz

    @Test
    fun octaves_notes0_57_65_127_fewestOctavesIntoANarrowAndAWideProfile() {
        // Narrow 120–240 Hz: C-1 (8.18 Hz) up 4 octaves to C3, A3 (220 Hz) fits, F4 down 1 to F3, G9 (12.5 kHz) down 6 to G3.
        assertEquals(130.8127826502993, played(0, 120.0, 240.0, PitchFit.OCTAVES), 1e-9)
        assertEquals(220.0, played(57, 120.0, 240.0, PitchFit.OCTAVES), 1e-9)
        assertEquals(174.61411571650194, played(65, 120.0, 240.0, PitchFit.OCTAVES), 1e-9)
        assertEquals(195.99771799087463, played(127, 120.0, 240.0, PitchFit.OCTAVES), 1e-9)
        // Wide 50–300 Hz: the fewest octaves that reach it, so C-1 goes up 3 (C2, 65.4 Hz), not to the range's middle.
        assertEquals(65.40639132514966, played(0, 50.0, 300.0, PitchFit.OCTAVES), 1e-9)
        assertEquals(220.0, played(57, 50.0, 300.0, PitchFit.OCTAVES), 1e-9)
        assertEquals(174.61411571650194, played(65, 50.0, 300.0, PitchFit.OCTAVES), 1e-9)
        assertEquals(195.99771799087463, played(127, 50.0, 300.0, PitchFit.OCTAVES), 1e-9)
        assertEquals(3, note(0).fitPitchInto(50.0, 300.0).octaves)
        assertEquals(-6, note(127).fitPitchInto(50.0, 300.0).octaves)
    }

    @Test
    fun clamp_notes0_57_65_127_toTheNearestEndOfANarrowAndAWideProfile() {
        assertEquals(listOf(120.0, 220.0, 240.0, 240.0), listOf(0, 57, 65, 127).map { played(it, 120.0, 240.0, PitchFit.CLAMP) })
        assertEquals(listOf(50.0, 220.0, 300.0, 300.0), listOf(0, 57, 65, 127).map { played(it, 50.0, 300.0, PitchFit.CLAMP) })
    }

    @Test
    fun octaves_noShiftReachesARangeNarrowerThanAnOctave_closestThenClamped() {
        // 150–200 Hz holds no A (110, 220 Hz): 220 overhangs by log2(220/200) = 0.14 octave, 110 by 0.45, so it stays and clamps.
        val fitted = note(57).fitPitchInto(150.0, 200.0)
        assertEquals(0, fitted.octaves)
        assertEquals(200.0, fitted.pattern.frequency.single().hertz, 0.0)
        assertEquals("clamped to 150–200 Hz", fitted.summary)
    }

    @Test
    fun badRange_throws() {
        assertThrows(IllegalArgumentException::class.java) { stroke.fitPitchInto(200.0, 100.0) }
        assertThrows(IllegalArgumentException::class.java) { stroke.fitPitchInto(Double.NaN, 100.0) }
    }
}
