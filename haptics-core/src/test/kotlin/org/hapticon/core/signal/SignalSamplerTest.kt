package org.hapticon.core.signal

import org.hapticon.core.render.stream
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Test

class SignalSamplerTest {
    @Test
    fun stream_asr_hasRoundedCountAndSamplesAtIOverFs() {
        // 1 ms up to 1, 1 ms hold, 1 ms down, at 4 kHz: round(0.003 · 4000) = 12 samples.
        val stream = Asr(0.001, 0.001, 0.001).stream(4_000)
        assertEquals(12L, stream.totalSamples)
        val out = FloatArray(12)
        assertEquals(12, stream.read(out))
        assertArrayEquals(floatArrayOf(0f, 0.25f, 0.5f, 0.75f, 1f, 1f, 1f, 1f, 1f, 0.75f, 0.5f, 0.25f), out, 1e-6f)
        assertEquals(-1, stream.read(out))
    }

    @Test
    fun stream_sumAboveFullScale_isClampedToOne() {
        val loud = Asr(0.0, 0.001, 0.0, 0.75) + Asr(0.0, 0.001, 0.0, 0.75)
        val out = FloatArray(4)
        loud.stream(4_000).read(out)
        assertArrayEquals(floatArrayOf(1f, 1f, 1f, 1f), out, 0f)
    }

    @Test(expected = IllegalArgumentException::class)
    fun stream_infiniteSignal_throws() {
        Sine(1.0).stream(8_000)
    }
}
