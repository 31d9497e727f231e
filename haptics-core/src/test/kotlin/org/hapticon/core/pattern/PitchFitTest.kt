package org.hapticon.core.pattern

import org.hapticon.core.HapticIcon
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

    @Test
    fun badRange_throws() {
        assertThrows(IllegalArgumentException::class.java) { stroke.fitPitchInto(200.0, 100.0) }
        assertThrows(IllegalArgumentException::class.java) { stroke.fitPitchInto(Double.NaN, 100.0) }
    }
}
