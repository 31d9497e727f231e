package org.hapticon.study.analysis

import kotlin.math.abs
import kotlin.math.min
import kotlin.math.sign
import kotlin.math.sqrt

/**
 * The Wilcoxon signed-rank test on paired samples, two-sided, following R's `wilcox.test(paired = TRUE)`:
 * zero differences are dropped ([zeros]), |differences| are ranked with ties given their average rank,
 * [v] is the sum of the ranks of the positive differences over the [n] non-zero ones. [p] is exact
 * ([exact] true) when n < 50 and there are no ties and no zeros; otherwise it is the normal approximation
 * with continuity correction and the tie correction of the variance. Null [p] with [undefinedReason]
 * when no non-zero difference is left.
 */
public data class WilcoxonSignedRank(
    val n: Int,
    val zeros: Int,
    val ties: Boolean,
    val v: Double,
    val p: Double?,
    val exact: Boolean,
    val undefinedReason: String?,
) {
    public companion object {
        /** Largest n with an exact p, as in R. */
        public const val EXACT_LIMIT: Int = 50

        /** Tests [a] against [b], paired by index; both must be the same size and finite. */
        public fun of(a: List<Double>, b: List<Double>): WilcoxonSignedRank {
            val all = pairedDifferences(a, b)
            val differences = all.filter { it != 0.0 }
            val zeros = all.size - differences.size
            val n = differences.size
            if (n == 0) {
                return WilcoxonSignedRank(0, zeros, false, 0.0, null, false, "no non-zero differences among ${all.size} pairs")
            }
            val ranks = averageRanks(differences.map { abs(it) })
            val v = differences.indices.sumOf { if (differences[it] > 0.0) ranks[it] else 0.0 }
            val tieGroups = differences.map { abs(it) }.groupingBy { it }.eachCount().values.filter { it > 1 }
            val ties = tieGroups.isNotEmpty()
            if (n < EXACT_LIMIT && !ties && zeros == 0) {
                return WilcoxonSignedRank(n, zeros, false, v, exactP(v.toInt(), n), true, null)
            }
            val centred = v - n * (n + 1) / 4.0
            val tieCorrection = tieGroups.sumOf { t -> t.toDouble() * t * t - t } / 48.0
            val sigma = sqrt(n * (n + 1.0) * (2 * n + 1) / 24.0 - tieCorrection)
            val z = (centred - sign(centred) * 0.5) / sigma
            return WilcoxonSignedRank(n, zeros, ties, v, min(1.0, SpecialFunctions.normalTwoSided(z)), false, null)
        }

        /** R's exact two-sided p: 2 · the smaller tail of the signed-rank distribution at [v], capped at 1. */
        private fun exactP(v: Int, n: Int): Double {
            val counts = signedRankCounts(n)
            val total = Math.scalb(1.0, n)
            val tail = if (v > n * (n + 1) / 4.0) {
                (v until counts.size).sumOf { counts[it].toDouble() } // P(V ≥ v)
            } else {
                (0..v).sumOf { counts[it].toDouble() } // P(V ≤ v)
            }
            return min(1.0, 2.0 * tail / total)
        }

        /** How many subsets of {1..n} have each rank sum 0..n(n+1)/2 (exact in a Long for n < 64). */
        private fun signedRankCounts(n: Int): LongArray {
            val maxSum = n * (n + 1) / 2
            val counts = LongArray(maxSum + 1)
            counts[0] = 1
            for (rank in 1..n) {
                for (s in maxSum downTo rank) counts[s] += counts[s - rank]
            }
            return counts
        }
    }
}

/** Ranks 1..n of [values], ties given the average of the ranks they span (R's `rank`, ties "average"). */
internal fun averageRanks(values: List<Double>): DoubleArray {
    val order = values.indices.sortedBy { values[it] }
    val ranks = DoubleArray(values.size)
    var i = 0
    while (i < order.size) {
        var j = i
        while (j + 1 < order.size && values[order[j + 1]] == values[order[i]]) j++
        val average = (i + j) / 2.0 + 1.0
        for (k in i..j) ranks[order[k]] = average
        i = j + 1
    }
    return ranks
}
