package org.hapticon.study.analysis

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

/**
 * Published reference values: R's `sleep` data (Student 1908), R 4.x
 * `t.test(extra ~ group, data = sleep, paired = TRUE)` → t = -4.0621, df = 9, p-value = 0.002833;
 * `wilcox.test(..., paired = TRUE)` → V = 0, p-value = 0.009091 (ties and a zero: normal approximation).
 * Cross-checked to full precision with scipy (`ttest_rel`, `wilcoxon(method="approx", correction=True)`).
 */
class StatisticsTest {
    private val group1 = listOf(0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0)
    private val group2 = listOf(1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4)

    @Test fun pairedTTestOnSleepMatchesR() {
        val test = PairedTTest.of(group1, group2)
        assertEquals(10, test.n)
        assertEquals(9, test.df)
        assertEquals(-4.062127683382037, test.t!!, 1e-12)
        assertEquals(0.002832890197384273, test.p!!, 0.002832890197384273 * 1e-10)
        assertEquals(-1.58, test.meanDifference!!, 1e-12)
        assertEquals(1.2299954832798732, test.sdDifference!!, 1e-12)
        assertEquals(-1.2845575625910546, test.cohensDz!!, 1e-12) // d_z = mean / SD of differences
        assertNull(test.undefinedReason)
    }

    @Test fun wilcoxonOnSleepMatchesR() {
        val test = WilcoxonSignedRank.of(group1, group2)
        assertEquals(0.0, test.v, 0.0)
        assertEquals(9, test.n)
        assertEquals(1, test.zeros)
        assertTrue(test.ties)
        assertFalse(test.exact)
        assertEquals(0.009090698015925044, test.p!!, 0.009090698015925044 * 1e-10)
    }

    /** R's `?wilcox.test` example (Hollander & Wolfe, depression scale): V = 40, two-sided p = 0.03906 = 20/512. */
    @Test fun wilcoxonExactMatchesR() {
        val x = listOf(1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30)
        val y = listOf(0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29)
        val test = WilcoxonSignedRank.of(x, y)
        assertEquals(40.0, test.v, 0.0)
        assertTrue(test.exact)
        assertEquals(0.0390625, test.p!!, 1e-15)
        // Swapped, V is the other tail's sum (45 − 40) and p is the same.
        val swapped = WilcoxonSignedRank.of(y, x)
        assertEquals(5.0, swapped.v, 0.0)
        assertEquals(0.0390625, swapped.p!!, 1e-15)
    }

    @Test fun wilcoxonExactSmallCases() {
        // n = 1: V = 1 > n(n+1)/4, P(V ≥ 1) = 1/2, doubled = 1.
        assertEquals(1.0, WilcoxonSignedRank.of(listOf(2.0), listOf(1.0)).p!!, 0.0)
        // n = 5 all positive: P(V ≥ 15) = 1/32, two-sided 1/16.
        assertEquals(0.0625, WilcoxonSignedRank.of(listOf(1.0, 2.0, 3.0, 4.0, 5.0), listOf(0.0, 0.0, 0.0, 0.0, 0.0)).p!!, 1e-15)
    }

    @Test fun wilcoxonWithoutNonZeroDifferencesIsUndefined() {
        val test = WilcoxonSignedRank.of(listOf(3.0, 4.0), listOf(3.0, 4.0))
        assertNull(test.p)
        assertEquals(2, test.zeros)
        assertEquals("no non-zero differences among 2 pairs", test.undefinedReason)
        assertNull(WilcoxonSignedRank.of(emptyList(), emptyList()).p)
    }

    @Test fun tTestUndefinedCasesSayWhy() {
        val one = PairedTTest.of(listOf(3.0), listOf(1.0))
        assertNull(one.t)
        assertNull(one.p)
        assertEquals("needs at least 2 pairs, has 1", one.undefinedReason)
        assertEquals(2.0, one.meanDifference!!, 0.0)
        val empty = PairedTTest.of(emptyList(), emptyList())
        assertNull(empty.meanDifference)
        assertEquals(0, empty.df)
        val constant = PairedTTest.of(listOf(4.0, 5.0, 3.0), listOf(3.0, 4.0, 2.0))
        assertNull(constant.t)
        assertNull(constant.cohensDz)
        assertEquals("all 3 differences are equal (SD 0)", constant.undefinedReason)
        val zeros = PairedTTest.of(listOf(4.0, 5.0), listOf(4.0, 5.0))
        assertNull(zeros.p)
    }

    @Test fun nonFiniteOrMismatchedInputIsRejected() {
        val nan = assertThrows(IllegalArgumentException::class.java) { PairedTTest.of(listOf(1.0, Double.NaN), listOf(1.0, 2.0)) }
        assertEquals("first sample value 2 is NaN; responses must be finite numbers", nan.message)
        assertThrows(IllegalArgumentException::class.java) { WilcoxonSignedRank.of(listOf(1.0), listOf(Double.POSITIVE_INFINITY)) }
        val sizes = assertThrows(IllegalArgumentException::class.java) { PairedTTest.of(listOf(1.0, 2.0), listOf(1.0)) }
        assertEquals("paired samples differ in size: 2 and 1", sizes.message)
    }

    @Test fun hugeSamplesStayFinite() {
        val a = List(10_000) { (it % 5) + 1.0 }
        val b = List(10_000) { ((it + 1) % 5) + 1.0 }
        val t = PairedTTest.of(a, b)
        assertEquals(9_999, t.df)
        assertTrue(t.p!! in 0.0..1.0)
        val w = WilcoxonSignedRank.of(a, b)
        assertFalse(w.exact)
        assertTrue(w.p!! in 0.0..1.0)
    }

    @Test fun descriptivesUseRType7Quantiles() {
        // numpy.percentile (linear = R type 7) of 1,2,2,3,5,4,4,5: 2, 3.5, 4.25; mean 3.25, SD 1.4880476182856899.
        val d = Descriptives.of(listOf(1.0, 2.0, 2.0, 3.0, 5.0, 4.0, 4.0, 5.0))
        assertEquals(8, d.n)
        assertEquals(3.25, d.mean, 0.0)
        assertEquals(1.4880476182856899, d.sd!!, 1e-14)
        assertEquals(3.5, d.median, 0.0)
        assertEquals(2.0, d.q1, 0.0)
        assertEquals(4.25, d.q3, 0.0)
        assertEquals(2.25, d.iqr, 0.0)
        assertEquals(1.0, d.min, 0.0)
        assertEquals(5.0, d.max, 0.0)
    }

    @Test fun descriptivesOfOneValue() {
        val d = Descriptives.of(listOf(4.0))
        assertNull(d.sd)
        assertEquals(4.0, d.median, 0.0)
        assertEquals(0.0, d.iqr, 0.0)
        assertThrows(IllegalArgumentException::class.java) { Descriptives.of(emptyList()) }
        assertThrows(IllegalArgumentException::class.java) { Descriptives.of(listOf(1.0, Double.NaN)) }
    }

    @Test fun holmMatchesRPAdjust() {
        // R: p.adjust(c(0.01, 0.02, 0.03, 0.04, 0.05), "holm") = 0.05 0.08 0.09 0.09 0.09
        val adjusted = Holm.adjust(listOf(0.01, 0.02, 0.03, 0.04, 0.05))
        listOf(0.05, 0.08, 0.09, 0.09, 0.09).forEachIndexed { i, p -> assertEquals(p, adjusted[i], 1e-15) }
        // Order is kept: 0.001·3 = 0.003, 0.03·2 = 0.06, then max(0.06, 0.04·1).
        val unordered = Holm.adjust(listOf(0.04, 0.001, 0.03))
        listOf(0.06, 0.003, 0.06).forEachIndexed { i, p -> assertEquals(p, unordered[i], 1e-15) }
        assertEquals(listOf(1.0), Holm.adjust(listOf(1.0)))
        assertEquals(emptyList<Double>(), Holm.adjust(emptyList()))
        assertEquals(1.0, Holm.adjust(listOf(0.6, 0.7))[0], 0.0) // capped at 1
        assertThrows(IllegalArgumentException::class.java) { Holm.adjust(listOf(Double.NaN)) }
    }
}
