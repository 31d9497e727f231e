package org.hapticon.gesture.social

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Test

class SocialTouchFeaturesTest {
    /** Three elements in a row at x = 0, 1, 2 (y = 0). */
    private val row3 = SkinLayout.grid(3, 1, 0.0, 2.0, 0.0, 0.0)

    private fun f(t: Double, vararg e: Double, joint: Double = 0.0) = SkinFrame(t, e, joint)

    @Test
    fun names_areTable1sThirteenInItsOrder() {
        assertEquals(
            listOf(
                "max_intensity", "min_intensity", "max_joint", "min_joint", "x", "y", "displacement",
                "spatial_resolution", "mean_spatial_resolution", "duration_s", "max_rise_rate", "max_fall_rate", "touch_count",
            ),
            SocialTouchFeatures.NAMES,
        )
    }

    @Test
    fun features_twoTouches_areTable1sDefinitionsAveragedPerTouch() {
        // 10 Hz. Touch 1 at 0.1–0.2 s (off at 0.3), touch 2 at 0.5 s (off at 0.6).
        val stream = listOf(
            f(0.0, 0.0, 0.0, 0.0),
            f(0.1, 1.0, 0.8, 0.0, joint = 0.1),
            f(0.2, 2.0, 1.6, 0.2, joint = 0.3),
            f(0.3, 0.0, 0.0, 0.0),
            f(0.4, 0.0, 0.0, 0.0),
            f(0.5, 0.0, 0.5, 1.0, joint = -0.2),
            f(0.6, 0.0, 0.0, 0.0),
        )
        val x = SocialTouchFeatures.of(row3, stream.asSequence())
        // Touch 1: max 2 at 0.2 s, where ≥ 1.5 (75 %) are elements 0 and 1 (x 0.5) and ≥ 1.0 (50 %) 2 of 3; min 0;
        // joint 0.1..0.3; centroids 0.5 then 0.5 (no displacement); 0.2 s; rises 10/s, falls 20/s (2 → 0 in 0.1 s).
        // Touch 2: max 1 at 0.5 s, ≥ 0.75 only element 2 (x 2), ≥ 0.5 2 of 3; joint −0.2; 0.1 s; rise and fall 10/s.
        val expected = doubleArrayOf(
            (2.0 + 1.0) / 2, 0.0, (0.3 - 0.2) / 2, (0.1 - 0.2) / 2, (0.5 + 2.0) / 2, 0.0, 0.0,
            2.0 / 3, 2.0 / 3, (0.2 + 0.1) / 2, (10.0 + 10.0) / 2, (20.0 + 10.0) / 2, 2.0,
        )
        assertArrayEquals(expected, x, 1e-9)
    }

    @Test
    fun features_aStroke_movesItsCentroidAndReportsTheDisplacementAndPeakLocation() {
        // A 5 × 1 strip at x 0..4: one element lit at a time, walking from x 0 to 4; the strongest at x 3.
        val strip = SkinLayout.grid(5, 1, 0.0, 4.0, 0.0, 0.0)
        val levels = doubleArrayOf(0.4, 0.5, 0.6, 0.9, 0.7)
        val stream = (0..4).map { k -> SkinFrame(k * 0.025, DoubleArray(5) { if (it == k) levels[k] else 0.0 }) }
        val x = SocialTouchFeatures.of(strip, stream.asSequence())
        assertEquals(4.0, x[6], 1e-12) // displacement: first centroid x 0, last x 4
        assertEquals(3.0, x[4], 1e-12) // location at the maximum's frame
        assertEquals(0.2, x[7], 1e-12) // one element of five at ≥ 50 %
        assertEquals(0.1, x[9], 1e-12) // 0 → 0.1 s, the stream ending in contact
        assertEquals(1.0, x[12], 0.0)
    }

    @Test
    fun features_theCentroidIsOfElementsAtLeast75PercentOfTheMaximum_unweighted() {
        // Elements at x 0, 1, 2 holding 1.0, 0.75, 0.74: the first two qualify, each counted once → x 0.5.
        val x = SocialTouchFeatures.of(row3, sequenceOf(f(0.0, 1.0, 0.75, 0.74)))
        assertEquals(0.5, x[4], 1e-12)
        assertEquals(1.0, x[7], 1e-12) // all three ≥ 0.5
    }

    @Test
    fun features_aTouchSeenOnlyByTheJointSensor_isLocatedAtTheOrigin() {
        val stream = sequenceOf(f(0.0, 0.0, 0.0, 0.0), f(0.1, 0.0, 0.0, 0.0, joint = 0.4), f(0.2, 0.0, 0.0, 0.0, joint = 0.6), f(0.3, 0.0, 0.0, 0.0))
        val x = SocialTouchFeatures.of(row3, stream)
        assertArrayEquals(doubleArrayOf(0.0, 0.0, 0.6, 0.4, 0.0, 0.0, 0.0, 0.0, 0.0, 0.2, 0.0, 0.0, 1.0), x, 1e-12)
    }

    @Test
    fun features_belowTheThresholdOrEmpty_areAllZero() {
        assertArrayEquals(DoubleArray(13), SocialTouchFeatures.of(row3, emptySequence()), 0.0)
        val faint = sequenceOf(f(0.0, 0.05, 0.0, 0.0, joint = -0.05), f(0.1, 0.04, 0.01, 0.0))
        assertArrayEquals(DoubleArray(13), SocialTouchFeatures.of(row3, faint), 0.0)
        assertEquals(1.0, SocialTouchFeatures.of(row3, faint, TouchThresholds(0.01, 1.0))[12], 0.0)
    }

    @Test
    fun offer_wrongSizeNonFiniteOrBackwardsFrames_areSkippedAndCounted() {
        val features = SocialTouchFeatures(row3)
        features.offer(f(1.0, 1.0, 0.0, 0.0))
        features.offer(f(1.1, 1.0, 0.0))
        features.offer(f(Double.NaN, 1.0, 0.0, 0.0))
        features.offer(f(0.5, 1.0, 0.0, 0.0))
        features.offer(f(1.2, 1.0, Double.NaN, 0.0))
        features.offer(f(1.3, 1.0, 0.0, 0.0, joint = Double.POSITIVE_INFINITY))
        assertEquals(5, features.skippedFrames)
        assertEquals(1.0, features.features()[12], 0.0)
    }

    @Test
    fun features_hourLongStream_countsEveryTouchInConstantMemory() {
        // One hour at 40 Hz on a 16-element pad, generated lazily: a 0.5 s touch every 2 s (from frame 1), 1800 touches.
        val pad = SkinLayout.grid(4, 4)
        val frames = generateSequence(0L) { it + 1 }.take(144_000).map { k -> SkinFrame(k / 40.0, DoubleArray(16) { if (k % 80 in 1..20) 0.5 else 0.0 }) }
        val x = SocialTouchFeatures.of(pad, frames)
        assertEquals(1800.0, x[12], 0.0)
        assertEquals(0.5, x[9], 1e-9) // on at k, off at k + 20: 20 frames of 25 ms
        assertEquals(20.0, x[10], 1e-9) // 0 → 0.5 in 25 ms
    }

    @Test
    fun touchPad_drawsAContactAsADiscOfItsArea_andAlwaysTheElementUnderTheFinger() {
        val pad = TouchPadSkin(columns = 5, rows = 5)
        val point = pad.frame(ContactFrame(0.0, 0.7, 0.5, 0.5, 0.0)).elements
        assertEquals(listOf(12), point.indices.filter { point[it] > 0 })
        assertEquals(0.7, point[12], 0.0)
        // Area π·0.25² → radius 0.25: the centre and its four neighbours 0.25 away.
        val disc = pad.frame(ContactFrame(0.0, 0.7, 0.5, 0.5, Math.PI * 0.0625)).elements
        assertEquals(listOf(7, 11, 12, 13, 17), disc.indices.filter { disc[it] > 0 })
        assertArrayEquals(DoubleArray(25), pad.frame(ContactFrame(0.0, 0.0, 0.5, 0.5, 0.3)).elements, 0.0)
    }

    @Test
    fun ofContacts_countsEachFingerDownAsATouch() {
        val stream = sequenceOf(
            ContactFrame(0.00, 0.5, 0.2, 0.5, 0.01), ContactFrame(0.05, 0.0, 0.0, 0.0, 0.0),
            ContactFrame(0.10, 0.6, 0.8, 0.5, 0.01), ContactFrame(0.15, 0.0, 0.0, 0.0, 0.0),
        )
        val x = SocialTouchFeatures.ofContacts(stream)
        assertEquals(2.0, x[12], 0.0)
        assertEquals(0.55, x[0], 1e-12)
        assertEquals(0.05, x[9], 1e-12)
    }
}
