package org.hapticon.study.analysis

import kotlin.math.abs
import kotlin.math.sqrt

/**
 * A paired-samples (one-sample on differences a − b) Student t-test, two-sided. [n] pairs,
 * [meanDifference] and [sdDifference] of the differences, t = mean / (sd / √n) with [df] = n − 1, and
 * Cohen's d for paired data in its d_z form: mean difference / SD of the differences (not d_av, which
 * divides by the mean of the two groups' SDs). When the test is undefined (fewer than 2 pairs, or every
 * difference equal so sd = 0) [t], [p] and [cohensDz] are null and [undefinedReason] says why.
 */
public data class PairedTTest(
    val n: Int,
    val meanDifference: Double?,
    val sdDifference: Double?,
    val t: Double?,
    val df: Int,
    val p: Double?,
    val cohensDz: Double?,
    val undefinedReason: String?,
) {
    public companion object {
        /**
         * The two-sided p of a t statistic [t] with [df] degrees of freedom, as [of] computes it: the check of a
         * published "t(15) = 2.423, p < 0.05".
         */
        public fun twoSidedP(t: Double, df: Int): Double {
            require(t.isFinite() && df >= 1) { "need a finite t and df >= 1, were $t and $df" }
            return SpecialFunctions.studentTTwoSided(t, df.toDouble())
        }

        /** Tests [a] against [b], paired by index; both must be the same size and finite. */
        public fun of(a: List<Double>, b: List<Double>): PairedTTest {
            val differences = pairedDifferences(a, b)
            val n = differences.size
            if (n < 2) {
                return PairedTTest(n, differences.firstOrNull(), null, null, maxOf(n - 1, 0), null, null, "needs at least 2 pairs, has $n")
            }
            val mean = differences.average()
            val sd = sampleSd(differences, mean)!!
            // R's rule ("data are essentially constant"): a spread at rounding level is no spread, t would be ±1e16.
            if (sd / sqrt(n.toDouble()) < 10 * Math.ulp(1.0) * abs(mean) || sd == 0.0) {
                return PairedTTest(n, mean, sd, null, n - 1, null, null, "all $n differences are equal (SD 0)")
            }
            val t = mean / (sd / sqrt(n.toDouble()))
            val p = SpecialFunctions.studentTTwoSided(t, (n - 1).toDouble())
            return PairedTTest(n, mean, sd, t, n - 1, p, mean / sd, null)
        }
    }
}

/** The differences a[i] − b[i]; [IllegalArgumentException] when sizes differ or any value is not finite. */
internal fun pairedDifferences(a: List<Double>, b: List<Double>): List<Double> {
    require(a.size == b.size) { "paired samples differ in size: ${a.size} and ${b.size}" }
    requireFinite(a, "first sample")
    requireFinite(b, "second sample")
    return a.indices.map { a[it] - b[it] }
}
