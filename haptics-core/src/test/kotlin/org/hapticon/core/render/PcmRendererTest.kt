package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import kotlin.math.abs
import kotlin.math.sqrt

class PcmRendererTest {
    @Test
    fun toShortArray_everySample_isPcm16OfTheExactSample() {
        for (model in EnvelopeModel.values()) {
            val pcm = PcmRenderer(HapticIcon.KNOCK, 44_100, model).toShortArray()
            val renderer = IconRenderer(HapticIcon.KNOCK, 44_100, model)
            assertEquals(24_696, pcm.size)
            for (i in pcm.indices) {
                assertEquals("$model $i", IconReference.pcm(renderer.sampleAt(i.toLong())), pcm[i].toInt())
            }
        }
    }

    @Test
    fun stream_blocksOf7_equalWholeRender() {
        val renderer = PcmRenderer(HapticIcon.HIT, 48_000, EnvelopeModel.PROCESSING, RenderMode.FAST)
        val whole = renderer.toShortArray()
        val streamed = ShortArray(whole.size)
        val stream = renderer.stream()
        assertEquals(73_920L, stream.totalSamples)
        var filled = 0
        while (true) {
            val n = stream.read(streamed, filled, minOf(7, streamed.size - filled))
            if (n < 0) break
            filled += n
            assertEquals(filled.toLong(), stream.position)
        }
        assertArrayEquals(whole, streamed)
    }

    @Test
    fun fidelity_exactMode_matchesErrorsComputedFromTheRender() {
        val renderer = PcmRenderer(HapticIcon.HIT, 48_000)
        val pcm = renderer.toShortArray()
        val ideal = IconRenderer(HapticIcon.HIT, 48_000)
        var sum = 0.0
        var max = 0.0
        for (i in pcm.indices) {
            val error = abs(pcm[i] / 32767.0 - ideal.sampleAt(i.toLong()))
            sum += error * error
            max = maxOf(max, error)
        }
        val fidelity = renderer.fidelity()
        assertEquals(sqrt(sum / pcm.size), fidelity.rmsError, 1e-15)
        assertEquals(max, fidelity.maxError, 0.0)
        // Rounding to the nearest step bounds the error by half a step.
        assertTrue(fidelity.maxError <= 0.5 / 32767)
        // Uniform rounding error has rms step/√12 ≈ 8.8e-6 where the icon plays (hit is silent 30 % of
        // the time, where the error is 0); a broken render would be far off.
        assertTrue("${fidelity.rmsError}", fidelity.rmsError > 6e-6 && fidelity.rmsError < 8.8e-6)
        assertTrue(fidelity.description, fidelity.description.contains("48000 Hz"))
    }

    @Test
    fun fidelity_fastMode_staysWithinHalfAStepPlus1e6() {
        val fidelity = PcmRenderer(HapticIcon.STROKE, 96_000, EnvelopeModel.PAPER, RenderMode.FAST).fidelity()
        assertTrue("${fidelity.maxError}", fidelity.maxError <= 0.5 / 32767 + 1e-6)
        assertTrue("${fidelity.rmsError}", fidelity.rmsError > 7e-6 && fidelity.rmsError < 1e-5)
    }

    @Test
    fun fidelity_zeroSampleIcon_isZeroError() {
        val fidelity = PcmRenderer(HapticIcon("silent", 0.0, 0.0, 1.0, 0.0, 60.0), 48_000).fidelity()
        assertEquals(0.0, fidelity.rmsError, 0.0)
        assertEquals(0.0, fidelity.maxError, 0.0)
    }
}
