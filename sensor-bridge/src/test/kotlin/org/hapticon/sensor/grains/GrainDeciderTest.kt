package org.hapticon.sensor.grains

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import kotlin.math.PI
import kotlin.math.ln

class GrainDeciderTest {
    /** The cutoff that makes the filter coefficient exactly 1/2 at 1 kHz: e^(−2π·fc/fs) = 1/2. */
    private val halfCutoff = 1000.0 * ln(2.0) / (2 * PI)

    /** 9 grains = ten 1 N bins over 0–10 N, filter coefficient 1/2 at 1 kHz, grains of [grainSeconds]. */
    private fun decider(grainSeconds: Double) =
        GrainDecider(GrainSettings(grainCount = 9, maxNewtons = 10.0, cutoffHz = halfCutoff, grainSeconds = grainSeconds), 1000.0)

    private fun onsets(decider: GrainDecider, forces: List<Double>): List<Int> = forces.indices.filter { decider.offer(forces[it]) }

    @Test
    fun offer_slowFullPress_firesExactlyTheRequestedGrainCount() {
        // Shaping Compliance: grains = bins − 1. A 20 s linear press over the default 0–10 N range at 1 kHz,
        // held at the top for 1 s, crosses each of the N inner edges once.
        for (grains in listOf(0, 9, 19, 39)) {
            val decider = GrainDecider(GrainSettings(grainCount = grains), 1000.0)
            val fired = (0 until 21_000).count { decider.offer(minOf(10.0, it / 2000.0)) }
            assertEquals("grains $grains", grains, fired)
            assertEquals(grains, decider.currentReferenceBin)
        }
    }

    @Test
    fun offer_slowFullPressAndRelease_firesTheCountEachWay() {
        for (grains in listOf(9, 19, 39)) {
            val decider = GrainDecider(GrainSettings(grainCount = grains, distribution = BinDistribution.CONVEX), 1000.0)
            val press = (0 until 21_000).map { minOf(10.0, it / 2000.0) }
            val fired = (press + press.reversed() + List(1000) { 0.0 }).count { decider.offer(it) }
            assertEquals("grains $grains", 2 * grains, fired)
        }
    }

    @Test
    fun lowPassFilter_coefficient_isOneMinusEToTheMinusTwoPiFcOverFs() {
        assertEquals(0.06089863257570738, LowPassFilter(10.0, 1000.0).coefficient, 1e-15)
        assertEquals(0.5, LowPassFilter(halfCutoff, 1000.0).coefficient, 1e-15)
    }

    @Test
    fun lowPassFilter_step_approachesAsOneMinusHalfToTheN() {
        val filter = LowPassFilter(halfCutoff, 1000.0)
        // The first sample initialises the state; then y_n = 1 − (1/2)^n.
        assertEquals(0.0, filter.filter(0.0), 0.0)
        assertEquals(listOf(0.5, 0.75, 0.875, 0.9375), List(4) { filter.filter(1.0) }.map { Math.round(it * 1e12) / 1e12 })
    }

    @Test
    fun lowPassFilter_firstSample_isPassedThrough() {
        assertEquals(7.5, LowPassFilter(1.0, 1000.0).filter(7.5), 0.0)
    }

    @Test
    fun lowPassFilter_cutoffAtOrAboveNyquistOrNonPositive_isRejected() {
        for (make in listOf({ LowPassFilter(500.0, 1000.0) }, { LowPassFilter(0.0, 1000.0) }, { LowPassFilter(10.0, 0.0) }, { LowPassFilter(Double.NaN, 1000.0) })) {
            try {
                make()
                fail("accepted")
            } catch (_: IllegalArgumentException) {
            }
        }
    }

    @Test
    fun grainSamples_isTheDurationRoundedUpToSamples() {
        assertEquals(20, GrainDecider(GrainSettings(grainSeconds = 0.020), 1000.0).grainSamples)
        assertEquals(13, GrainDecider(GrainSettings(grainSeconds = 0.0125), 1000.0).grainSamples)
        assertEquals(1, GrainDecider(GrainSettings(grainSeconds = 0.0001), 1000.0).grainSamples)
        assertEquals(3, decider(0.003).grainSamples)
        // Never rounded down into the grain being delivered: 10.25 ms at 1 kHz holds 11 samples, 9 ms exactly 9.
        assertEquals(11, GrainDecider(GrainSettings(grainSeconds = 0.01025), 1000.0).grainSamples)
        assertEquals(9, GrainDecider(GrainSettings(grainSeconds = 0.009), 1000.0).grainSamples)
    }

    @Test
    fun offer_firstSample_onlySetsTheReference() {
        val decider = decider(0.003)
        assertFalse(decider.offer(9.5))
        assertEquals(9, decider.currentReferenceBin)
    }

    @Test
    fun offer_aStepWithOneSampleGrains_firesAtEveryBinChange() {
        // Filtered 0, 2.2, 3.3, 3.85, 4.125, 4.2625 …: bins 0, 2, 3, 3, 4, 4 … (never reaching 4.4's 5th edge).
        assertEquals(listOf(1, 2, 4), onsets(decider(0.001), listOf(0.0) + List(10) { 4.4 }))
    }

    @Test
    fun offer_aStepWithThreeSampleGrains_suppressesAndCatchesUp() {
        // Grain at 1 (bin 2) plays during 1–3; bin 3 at sample 2 is held back; at 4 the bin is 4 ≠ 2: one grain.
        val decider = decider(0.003)
        assertEquals(listOf(1, 4), onsets(decider, listOf(0.0) + List(10) { 4.4 }))
        assertEquals(4, decider.currentReferenceBin)
        assertEquals(4.4, decider.filteredNewtons, 0.01)
    }

    @Test
    fun offer_aBinChangeUndoneWhileAGrainPlays_firesNothingMore() {
        // Filtered 0, 2.2, 3.3, 2.2, 2.2 …: bin 3 appears only while the 5-sample grain plays.
        assertEquals(listOf(1), onsets(decider(0.005), listOf(0.0, 4.4, 4.4, 1.1) + List(8) { 2.2 }))
        // The same input with 1-sample grains fires up and back down.
        assertEquals(listOf(1, 2, 3), onsets(decider(0.001), listOf(0.0, 4.4, 4.4, 1.1) + List(8) { 2.2 }))
    }

    @Test
    fun offer_releasing_firesGrainsOnTheWayDown() {
        // Filtered 8.8 (reference bin 8), 4.4 (bin 4), 2.2 (bin 2), 1.1 (bin 1), 0.55 (bin 0).
        assertEquals(listOf(1, 2, 3, 4), onsets(decider(0.001), listOf(8.8, 0.0, 0.0, 0.0, 0.0)))
    }

    @Test
    fun offer_nanOrInfinite_isSkippedButItsTimeStillCounts() {
        val decider = decider(0.003)
        // Grain at 1; samples 2 and 3 are NaN/∞ but end the grain; sample 4 filters 2.2 → 3.3 (bin 3 ≠ 2): grain.
        assertEquals(listOf(1, 4), onsets(decider, listOf(0.0, 4.4, Double.NaN, Double.POSITIVE_INFINITY, 4.4)))
        assertEquals(2L, decider.rejectedSamples)
        assertEquals(3.3, decider.filteredNewtons, 1e-12)
    }

    @Test
    fun isPlaying_coversExactlyTheGrainsSamples() {
        val decider = decider(0.003)
        decider.offer(0.0)
        assertTrue(decider.offer(4.4))
        assertTrue(decider.isPlaying)
        decider.offer(4.4)
        assertTrue(decider.isPlaying)
        decider.offer(4.4)
        assertTrue(decider.isPlaying)
        // Sample 4 is the first after the grain (it fires again here, so it plays once more).
        assertTrue(decider.offer(4.4))
        decider.offer(4.4)
        decider.offer(4.4)
        decider.offer(4.4)
        assertFalse(decider.isPlaying)
    }

    @Test
    fun reset_forgetsTheReferenceAndFilter() {
        val decider = decider(0.001)
        decider.offer(0.0)
        decider.offer(Double.NaN)
        decider.reset()
        assertEquals(-1, decider.currentReferenceBin)
        assertEquals(0L, decider.rejectedSamples)
        assertFalse(decider.offer(9.0))
        assertEquals(9, decider.currentReferenceBin)
    }
}
