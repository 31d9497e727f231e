package org.hapticon.gesture.extraction

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test
import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.sin

class SpectrumTest {
    @Test fun fftOfAnImpulseIsFlatAndOfACosineIsTwoBins() {
        val re = DoubleArray(8).also { it[0] = 1.0 }
        val im = DoubleArray(8)
        Spectrum.fft(re, im)
        for (k in 0 until 8) { assertEquals(1.0, re[k], 1e-15); assertEquals(0.0, im[k], 1e-15) }
        val n = 64
        val cr = DoubleArray(n) { cos(2 * PI * 5 * it / n) }
        val ci = DoubleArray(n)
        Spectrum.fft(cr, ci)
        for (k in 0 until n) assertEquals(if (k == 5 || k == n - 5) n / 2.0 else 0.0, cr[k], 1e-12)
        Spectrum.fft(DoubleArray(1), DoubleArray(1))
        assertThrows(IllegalArgumentException::class.java) { Spectrum.fft(DoubleArray(6), DoubleArray(6)) }
    }

    @Test fun dominantFrequencyIsWithinATenthOfAHertz() {
        for (f in listOf(110.0, 261.6256, 440.0, 1234.5)) {
            val x = DoubleArray(20_000) { sin(2 * PI * f * it / 44_100.0) + 0.3 }
            assertEquals(f, Spectrum.dominantFrequency(x, 44_100.0), 0.1)
        }
        assertEquals(0.0, Spectrum.dominantFrequency(DoubleArray(100) { 2.0 }, 1000.0), 0.0)
        assertEquals(0.0, Spectrum.dominantFrequency(DoubleArray(1), 1000.0), 0.0)
    }

    @Test fun noteRoundsAndClampsToRangeAndNyquist() {
        assertEquals(69, Spectrum.noteOf(440.0, 44_100.0))
        assertEquals(60, Spectrum.noteOf(261.6256, 44_100.0))
        assertEquals(60, Spectrum.noteOf(269.0, 44_100.0)) // 60.48 rounds down
        assertEquals(0, Spectrum.noteOf(1.0, 44_100.0))
        assertEquals(127, Spectrum.noteOf(20_000.0, 48_000.0))
        assertEquals(107, Spectrum.noteOf(5000.0, 8000.0)) // 3951 Hz is the last note below 4 kHz
        assertThrows(IllegalArgumentException::class.java) { Spectrum.noteOf(Double.NaN, 8000.0) }
    }
}
