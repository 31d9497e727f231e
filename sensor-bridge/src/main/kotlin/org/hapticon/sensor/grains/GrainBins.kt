package org.hapticon.sensor.grains

import kotlin.math.sqrt

/**
 * How a force range is cut into bins. With N bins over [Fmin, Fmax], edge k (k = 0..N) is
 * e_k = Fmin + (Fmax − Fmin)·F(k/N), where F is [shape]: F(0) = 0, F(1) = 1, increasing.
 */
public enum class BinDistribution {
    /** F(x) = x: equal-width bins. */
    LINEAR,

    /** F(x) = x²: narrow bins at light force, wide at strong force (grains crowd the start of a press). */
    CONVEX,

    /** F(x) = √x: wide bins at light force, narrow at strong force (grains crowd the end of a press). */
    CONCAVE,
    ;

    /** F(x) for x in [0, 1]. */
    public fun shape(x: Double): Double = when (this) {
        LINEAR -> x
        CONVEX -> x * x
        CONCAVE -> sqrt(x)
    }
}

/**
 * [count] force bins over [[minNewtons], [maxNewtons]] placed by [distribution]. Bin k holds forces with
 * e_k ≤ F < e_(k+1); forces below e_0 count as bin 0 and forces at or above e_N as bin N − 1, so every force
 * has a bin. The edges are computed once; [binOf] is a binary search over them (≤ 7 comparisons for 100
 * bins) and allocates nothing.
 */
public class GrainBins(
    /** Lower end of the range, in newtons. */
    public val minNewtons: Double,
    /** Upper end of the range, in newtons. */
    public val maxNewtons: Double,
    /** Number of bins, [MIN_COUNT]..[MAX_COUNT]. */
    public val count: Int,
    /** Where the edges fall. */
    public val distribution: BinDistribution,
) {
    init {
        require(count in MIN_COUNT..MAX_COUNT) { "grain count must be in $MIN_COUNT..$MAX_COUNT, was $count" }
        require(minNewtons.isFinite() && maxNewtons.isFinite() && minNewtons < maxNewtons) {
            "need finite minNewtons < maxNewtons, were $minNewtons and $maxNewtons"
        }
    }

    private val edgeArray = DoubleArray(count + 1) { k ->
        // Pin both ends so rounding can never shift the range.
        when (k) {
            0 -> minNewtons
            count -> maxNewtons
            else -> minNewtons + (maxNewtons - minNewtons) * distribution.shape(k.toDouble() / count)
        }
    }

    /** The N + 1 edges e_0 = min … e_N = max, in newtons. */
    public val edges: List<Double> get() = edgeArray.toList()

    /** The bin of [newtons] (0..[count] − 1); NaN maps to bin 0. Allocation-free. */
    public fun binOf(newtons: Double): Int {
        // Largest k in 0..count−1 with e_k ≤ force.
        var lo = 0
        var hi = count - 1
        while (lo < hi) {
            val mid = (lo + hi + 1) ushr 1
            if (edgeArray[mid] <= newtons) lo = mid else hi = mid - 1
        }
        return lo
    }

    public companion object {
        /** Fewest bins allowed. */
        public const val MIN_COUNT: Int = 1

        /** Most bins allowed. */
        public const val MAX_COUNT: Int = 100
    }
}
