package org.hapticon.gesture.social

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Test

class SocialTouchFeaturesTest {
    private fun frame(t: Double, i: Double, x: Double = 0.5, y: Double = 0.5, area: Double = if (i > 0) 2.0 else 0.0) = ContactFrame(t, i, x, y, area)

    @Test
    fun features_twoTouches_areAveragedPerTouch() {
        // 100 Hz: touch 1 at 0.01–0.03 s (1, 3, 2 at x 0.2), rest, touch 2 at 0.06–0.07 s (4, 4 at x 0.8).
        val stream = listOf(
            frame(0.00, 0.0), frame(0.01, 1.0, x = 0.2), frame(0.02, 3.0, x = 0.2), frame(0.03, 2.0, x = 0.2),
            frame(0.04, 0.0), frame(0.05, 0.0), frame(0.06, 4.0, x = 0.8, area = 4.0), frame(0.07, 4.0, x = 0.8, area = 6.0), frame(0.08, 0.0),
        )
        val f = SocialTouchFeatures.of(stream.asSequence())
        assertEquals(13, f.size)
        assertEquals((3.0 + 4.0) / 2, f[0], 1e-12) // intensity_max
        assertEquals((1.0 + 4.0) / 2, f[1], 1e-12) // intensity_min
        assertEquals((2.0 + 4.0) / 2, f[2], 1e-12) // intensity_mean
        assertEquals((0.2 + 0.8) / 2, f[3], 1e-12) // x
        assertEquals((2.0 + 6.0) / 2, f[5], 1e-12) // area_max
        assertEquals((2.0 + 5.0) / 2, f[6], 1e-12) // area_mean
        assertEquals((0.02 + 0.01) / 2, f[7], 1e-12) // duration_s
        // Rises: touch 1 (1 − 0)/0.01 = 100 then (3 − 1)/0.01 = 200; touch 2 (4 − 0)/0.01 = 400.
        assertEquals((200.0 + 400.0) / 2, f[8], 1e-9)
        // Falls: touch 1 (3 − 2)/0.01 = 100 then (2 − 0)/0.01 = 200; touch 2 (4 − 0)/0.01 = 400.
        assertEquals((200.0 + 400.0) / 2, f[9], 1e-9)
        assertEquals(2.0, f[10], 0.0)
        assertEquals(0.07 - 0.01, f[11], 1e-12)
        assertEquals(0.06 - 0.03, f[12], 1e-12)
    }

    @Test
    fun features_emptyOrNoContact_areAllZero() {
        assertArrayEquals(DoubleArray(13), SocialTouchFeatures.of(emptySequence()), 0.0)
        assertArrayEquals(DoubleArray(13), SocialTouchFeatures.of(sequenceOf(frame(0.0, 0.0), frame(1.0, 0.0))), 0.0)
    }

    @Test
    fun features_oneSample_isOneTouchOfNoDuration() {
        val f = SocialTouchFeatures.of(sequenceOf(frame(5.0, 2.0, x = 0.3, y = 0.9)))
        assertArrayEquals(doubleArrayOf(2.0, 2.0, 2.0, 0.3, 0.9, 2.0, 2.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0), f, 1e-12)
    }

    @Test
    fun features_hourLongStream_countsEveryTouchInConstantMemory() {
        // One hour at 100 Hz: a 0.5 s touch every 2 s, 1800 touches, 360,000 frames generated lazily.
        val frames = generateSequence(0L) { it + 1 }.take(360_000).map { k ->
            val t = k / 100.0
            frame(t, if (k % 200 < 50) 1.0 else 0.0)
        }
        val f = SocialTouchFeatures.of(frames)
        assertEquals(1800.0, f[10], 0.0)
        assertEquals(0.49, f[7], 1e-9)
        assertEquals(3598.49, f[11], 1e-6)
        assertEquals(1.51, f[12], 1e-6)
    }

    @Test
    fun offer_nanOrBackwardsFrames_areSkippedAndCounted() {
        val features = SocialTouchFeatures()
        features.offer(frame(1.0, 1.0))
        features.offer(frame(Double.NaN, 1.0))
        features.offer(frame(0.5, 1.0))
        features.offer(frame(1.01, Double.POSITIVE_INFINITY))
        assertEquals(3, features.skippedFrames)
        assertEquals(1.0, features.features()[10], 0.0)
    }
}
