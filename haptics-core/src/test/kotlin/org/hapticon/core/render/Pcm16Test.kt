package org.hapticon.core.render

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Test

class Pcm16Test {
    private fun pcm(x: Double): Int = Pcm16.fromSample(x).toInt()

    @Test
    fun fromSample_halfSteps_roundAwayFromZero() {
        assertEquals(1, pcm(0.5 / 32767))
        assertEquals(-1, pcm(-0.5 / 32767))
        assertEquals(2, pcm(1.5 / 32767))
        assertEquals(-2, pcm(-1.5 / 32767))
        assertEquals(3, pcm(2.5 / 32767))
        assertEquals(32767, pcm(32766.5 / 32767))
    }

    @Test
    fun fromSample_belowAHalfStep_roundsTowardZero() {
        assertEquals(0, pcm(0.49 / 32767))
        assertEquals(-1, pcm(-1.49 / 32767))
        assertEquals(16383, pcm(16383.49 / 32767))
        assertEquals(-16384, pcm(-16383.51 / 32767))
    }

    @Test
    fun fromSample_fullScaleAndBeyond_clipsToPlusMinus32767() {
        assertEquals(32767, pcm(1.0))
        assertEquals(-32767, pcm(-1.0))
        assertEquals(32767, pcm(1.5))
        assertEquals(-32767, pcm(-7.0))
        assertEquals(32767, pcm(Double.POSITIVE_INFINITY))
        assertEquals(-32767, pcm(Double.NEGATIVE_INFINITY))
    }

    @Test
    fun fromSample_nan_isSilence() {
        assertEquals(0, pcm(Double.NaN))
        assertEquals(0, Pcm16.fromSample(Float.NaN).toInt())
    }

    @Test
    fun convert_floatArrayRange_convertsEachSampleIntoTheDestinationRange() {
        val source = floatArrayOf(9f, 0.5f, -0.25f, 1f, Float.NaN, -1f)
        val destination = ShortArray(7) { 7 }
        Pcm16.convert(source, destination, sourceOffset = 1, destinationOffset = 2, length = 5)
        // 0.5 · 32767 = 16383.5 → 16384; −0.25 · 32767 = −8191.75 → −8192.
        assertArrayEquals(shortArrayOf(7, 7, 16384, -8192, 32767, 0, -32767), destination)
    }

    @Test(expected = IndexOutOfBoundsException::class)
    fun convert_destinationTooShort_throws() {
        Pcm16.convert(FloatArray(4), ShortArray(3))
    }
}
