package org.hapticon.app.ui

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.junit.Assert.assertEquals
import org.junit.Test

class EnvelopeOutlineTest {
    @Test
    fun envelopeOutline_hug_samplesAttackHoldAndRelease() {
        // Hug lasts 3 s; 7 points sit every 0.5 s: ramp 0→0.5 over 1.5 s, hold to 2.5 s, ramp to 0 at 3 s.
        val outline = envelopeOutline(HapticIcon.HUG, points = 7, model = EnvelopeModel.PAPER)

        val expected = floatArrayOf(0f, 0.5f / 3, 1f / 3, 0.5f, 0.5f, 0.5f, 0f)
        for (i in expected.indices) assertEquals("point $i", expected[i], outline[i], 1e-6f)
    }

    @Test
    fun envelopeOutline_defaultProcessingModel_startsRampFromPeakOne() {
        // Processing, the default: 0→1 over attack 1.5 s, then 1→0.5 over "sustain" 1 s.
        val outline = envelopeOutline(HapticIcon.HUG, points = 7)

        assertEquals(1f, outline[3], 1e-6f)
        assertEquals(0.75f, outline[4], 1e-6f)
        assertEquals(0.5f, outline[5], 1e-6f)
    }

    @Test(expected = IllegalArgumentException::class)
    fun envelopeOutline_onePoint_isRejected() {
        envelopeOutline(HapticIcon.HUG, points = 1)
    }
}
