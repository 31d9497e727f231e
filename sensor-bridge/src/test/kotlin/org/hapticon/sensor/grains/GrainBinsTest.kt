package org.hapticon.sensor.grains

import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test

class GrainBinsTest {
    @Test
    fun edges_linear_areEvenlySpaced() {
        assertEquals(listOf(0.0, 2.0, 4.0, 6.0, 8.0, 10.0), GrainBins(0.0, 10.0, 5, BinDistribution.LINEAR).edges)
        assertEquals(listOf(2.0, 4.0, 6.0, 8.0, 10.0, 12.0), GrainBins(2.0, 12.0, 5, BinDistribution.LINEAR).edges)
    }

    @Test
    fun edges_convex_areSquaresCrowdingLightForces() {
        // 16·(k/4)².
        assertEquals(listOf(0.0, 1.0, 4.0, 9.0, 16.0), GrainBins(0.0, 16.0, 4, BinDistribution.CONVEX).edges)
    }

    @Test
    fun edges_concave_areSquareRootsCrowdingStrongForces() {
        // 16·√(k/4) = 0, 8, 8√2, 8√3, 16.
        val edges = GrainBins(0.0, 16.0, 4, BinDistribution.CONCAVE).edges
        listOf(0.0, 8.0, 11.313708498984761, 13.856406460551018, 16.0).forEachIndexed { k, e -> assertEquals(e, edges[k], 1e-14) }
    }

    @Test
    fun binOf_atEdgesAndJustBelow_isTheBinStartingThere() {
        val bins = GrainBins(0.0, 10.0, 5, BinDistribution.LINEAR)
        assertEquals(0, bins.binOf(0.0))
        assertEquals(0, bins.binOf(Math.nextDown(2.0)))
        assertEquals(1, bins.binOf(2.0))
        assertEquals(4, bins.binOf(8.0))
        assertEquals(4, bins.binOf(Math.nextDown(10.0)))
    }

    @Test
    fun binOf_outsideTheRange_isTheEndBin() {
        val bins = GrainBins(0.0, 10.0, 5, BinDistribution.LINEAR)
        assertEquals(0, bins.binOf(-1.0))
        assertEquals(4, bins.binOf(10.0))
        assertEquals(4, bins.binOf(1e9))
        assertEquals(0, bins.binOf(Double.NEGATIVE_INFINITY))
        assertEquals(4, bins.binOf(Double.POSITIVE_INFINITY))
        assertEquals(0, bins.binOf(Double.NaN))
    }

    @Test
    fun binOf_convex_followsTheSquaredEdges() {
        val bins = GrainBins(0.0, 16.0, 4, BinDistribution.CONVEX)
        assertEquals(listOf(0, 1, 1, 2, 2, 3, 3), listOf(0.5, 1.0, 3.99, 4.0, 8.99, 9.0, 15.0).map { bins.binOf(it) })
    }

    @Test
    fun binOf_hundredBins_agreesWithALinearScanOfTheEdges() {
        for (distribution in BinDistribution.entries) {
            val bins = GrainBins(0.5, 20.0, 100, distribution)
            val edges = bins.edges
            for (step in -10..2100) {
                val force = step / 100.0
                var expected = 0
                for (k in 0 until 100) if (edges[k] <= force) expected = k
                assertEquals("$distribution at $force N", expected, bins.binOf(force))
            }
        }
    }

    @Test
    fun binOf_oneBin_isAlwaysZero() {
        val bins = GrainBins(0.0, 1.0, 1, BinDistribution.CONCAVE)
        assertEquals(listOf(0.0, 1.0), bins.edges)
        assertEquals(listOf(0, 0, 0), listOf(-5.0, 0.5, 5.0).map { bins.binOf(it) })
    }

    @Test
    fun constructor_countOutside1To100OrBadRange_isRejected() {
        GrainBins(0.0, 1.0, 100, BinDistribution.LINEAR)
        for (make in listOf(
            { GrainBins(0.0, 1.0, 0, BinDistribution.LINEAR) },
            { GrainBins(0.0, 1.0, 101, BinDistribution.LINEAR) },
            { GrainBins(1.0, 1.0, 10, BinDistribution.LINEAR) },
            { GrainBins(0.0, Double.POSITIVE_INFINITY, 10, BinDistribution.LINEAR) },
            { GrainBins(Double.NaN, 1.0, 10, BinDistribution.LINEAR) },
        )) {
            try {
                make()
                fail("accepted")
            } catch (_: IllegalArgumentException) {
            }
        }
    }

    @Test
    fun grainSettings_defaultsAndStudyRange() {
        val settings = GrainSettings()
        assertEquals(24, settings.grainCount)
        assertEquals(9, GrainSettings.STUDY_MIN_GRAIN_COUNT)
        assertEquals(39, GrainSettings.STUDY_MAX_GRAIN_COUNT)
        // Grains = bins − 1: 24 grains are 25 bins, 26 edges.
        assertEquals(25, settings.binCount)
        assertEquals(26, settings.bins.edges.size)
        assertEquals(0.02, settings.grainSeconds, 0.0)
        try {
            GrainSettings(grainCount = 100)
            fail("accepted")
        } catch (e: IllegalArgumentException) {
            assertEquals("grain count must be in 0..99, was 100", e.message)
        }
        assertEquals(1, GrainSettings(grainCount = 0).binCount)
        assertEquals(listOf(10, 20, 40), listOf(9, 19, 39).map { GrainSettings(grainCount = it).binCount })
    }
}
