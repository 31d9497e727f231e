package org.hapticon.gesture.extraction

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test
import kotlin.math.PI
import kotlin.math.sin
import kotlin.math.sqrt

class EnvelopesTest {
    @Test fun lowpassKeepsAConstantExactlyAndTracksARectifiedSine() {
        val constant = Envelopes.lowpass(DoubleArray(500) { 0.7 }, 1000.0, 20.0, rectify = false)
        for (v in constant) assertEquals(0.7, v, 1e-12)
        val sine = DoubleArray(44_100) { 0.6 * sin(2 * PI * 200.0 * it / 44_100.0) }
        val envelope = Envelopes.lowpass(sine, 44_100.0, 100.0, rectify = true)
        for (i in 5000 until 40_000 step 1000) assertEquals(0.6, envelope[i] * PI / 2, 0.003)
        assertEquals(0, Envelopes.lowpass(DoubleArray(0), 1000.0, 20.0, rectify = true).size)
    }

    @Test fun lowpassRejectsACutoffAtOrAboveNyquist() {
        val e = assertThrows(IllegalArgumentException::class.java) { Envelopes.lowpass(DoubleArray(4), 1000.0, 500.0, rectify = false) }
        assertEquals("low-pass cutoff must be in (0, 500.0) Hz (below Nyquist), was 500.0", e.message)
    }

    @Test fun rmsOverOnePeriodIsAmplitudeOverRootTwo() {
        val sine = DoubleArray(10_000) { 0.8 * sin(2 * PI * it / 100.0) }
        val rms = Envelopes.rms(sine, 100)
        for (i in 50 until 9950 step 97) assertEquals(0.8 / sqrt(2.0), rms[i], 1e-12)
        val x = doubleArrayOf(-3.0, 4.0, 0.0)
        assertArrayEquals(doubleArrayOf(3.0, 4.0, 0.0), Envelopes.rms(x, 1), 0.0)
        // Ends shrink the window: sample 0 of a 3-window sees samples 0 and 1.
        assertEquals(sqrt((9.0 + 16.0) / 2), Envelopes.rms(x, 3)[0], 1e-15)
    }

    @Test fun rmsDoesNotDriftOverMillionsOfSamples() {
        // Loud then very quiet: a running sum alone would keep rounding residue of the loud part.
        val x = DoubleArray(3_000_000) { if (it < 2_000_000) 1e3 else 1e-3 }
        val rms = Envelopes.rms(x, 1001)
        assertEquals(1e3, rms[1_000_000], 1e-9)
        assertEquals(1e-3, rms[2_999_000], 1e-15)
    }
}
