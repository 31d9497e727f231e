package org.hapticon.core.render

import org.hapticon.core.signal.Signal
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Test

class SignalStreamTest {
    /** [value] of t for [length] seconds. */
    private fun signal(length: Double, value: (Double) -> Double) = object : Signal {
        override val length: Double = length
        override fun sample(t: Double): Double = value(t)
    }

    @Test
    fun stream_ramp_hasRoundedCountAndSamplesAtIOverFs() {
        // t · 250 for 3 ms at 4 kHz: round(0.003 · 4000) = 12 samples, sample i = i / 16.
        val stream = signal(0.003) { it * 250.0 }.stream(4_000)
        assertEquals(12L, stream.totalSamples)
        val out = FloatArray(12)
        assertEquals(5, stream.read(out, 0, 5))
        assertEquals(5L, stream.position)
        assertEquals(7, stream.read(out, 5, 7))
        assertArrayEquals(FloatArray(12) { (it / 16.0).toFloat() }, out, 0f)
        assertEquals(-1, stream.read(out))
    }

    @Test
    fun stream_valuesPastFullScaleAndNaN_areClampedAndSilenced() {
        val values = doubleArrayOf(1.5, -2.0, Double.NaN, 0.25)
        val out = FloatArray(4)
        signal(0.001) { values[Math.round(it * 4_000).toInt()] }.stream(4_000).read(out)
        assertArrayEquals(floatArrayOf(1f, -1f, 0f, 0.25f), out, 0f)
    }

    @Test
    fun stream_asDoublesAndPcm_areTheClampedSamplesOnce() {
        val stream = signal(0.001) { if (it == 0.0) 2.0 else 0.5 }.stream(4_000) as DoubleSampleStream
        val doubles = DoubleArray(4)
        assertEquals(4, stream.read(doubles))
        assertArrayEquals(doubleArrayOf(1.0, 0.5, 0.5, 0.5), doubles, 0.0)
        val pcm = ShortArray(4)
        assertEquals(4, (signal(0.001) { 0.5 }.stream(4_000) as PcmStream).read(pcm))
        assertArrayEquals(ShortArray(4) { Pcm16.fromSample(0.5) }, pcm)
    }

    @Test(expected = IllegalArgumentException::class)
    fun stream_infiniteSignal_throws() {
        signal(Double.POSITIVE_INFINITY) { 0.0 }.stream(8_000)
    }
}
