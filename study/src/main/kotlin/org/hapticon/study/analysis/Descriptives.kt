package org.hapticon.study.analysis

import kotlin.math.floor
import kotlin.math.sqrt

/**
 * Summary of one sample: [n], [mean], sample standard deviation [sd] (n − 1 denominator; null when n < 2),
 * [median], quartiles [q1] and [q3], [min] and [max]. Quantiles follow R's default, type 7: the p-quantile
 * of sorted x₁..xₙ is x_{⌊h⌋+1} + (h − ⌊h⌋)(x_{⌊h⌋+2} − x_{⌊h⌋+1}) with h = (n − 1)p.
 */
public data class Descriptives(
    val n: Int,
    val mean: Double,
    val sd: Double?,
    val median: Double,
    val q1: Double,
    val q3: Double,
    val min: Double,
    val max: Double,
) {
    /** The interquartile range q3 − q1. */
    val iqr: Double get() = q3 - q1

    public companion object {
        /** The descriptives of [values]; throws [IllegalArgumentException] when empty or not all finite. */
        public fun of(values: List<Double>): Descriptives = of(values.toDoubleArray())

        /** The descriptives of [values] (not changed); as [of] for a list, without boxing a million values. */
        public fun of(values: DoubleArray): Descriptives {
            require(values.isNotEmpty()) { "cannot describe an empty sample" }
            val bad = values.indexOfFirst { !it.isFinite() }
            require(bad < 0) { "sample value ${bad + 1} is ${values[bad]}; responses must be finite numbers" }
            val sorted = values.copyOf().also { it.sort() }
            val mean = values.average()
            return Descriptives(
                n = values.size,
                mean = mean,
                sd = sampleSd(values, mean),
                median = quantile(sorted, 0.5),
                q1 = quantile(sorted, 0.25),
                q3 = quantile(sorted, 0.75),
                min = sorted.first(),
                max = sorted.last(),
            )
        }

        /** The R type 7 [p]-quantile of [sorted] (ascending, non-empty), p in [0, 1]. */
        public fun quantile(sorted: List<Double>, p: Double): Double = quantile(sorted.toDoubleArray(), p)

        /** As [quantile] for a list, over a sorted array. */
        public fun quantile(sorted: DoubleArray, p: Double): Double {
            require(sorted.isNotEmpty()) { "cannot take a quantile of an empty sample" }
            require(p in 0.0..1.0) { "quantile probability must be in [0, 1], got $p" }
            val h = (sorted.size - 1) * p
            val lower = floor(h).toInt()
            if (lower >= sorted.size - 1) return sorted.last()
            return sorted[lower] + (h - lower) * (sorted[lower + 1] - sorted[lower])
        }
    }
}

/** Sample standard deviation (n − 1) of [values] around [mean], two-pass; null when fewer than 2 values. */
internal fun sampleSd(values: List<Double>, mean: Double): Double? = sampleSd(values.toDoubleArray(), mean)

/** As [sampleSd] for a list. */
internal fun sampleSd(values: DoubleArray, mean: Double): Double? {
    if (values.size < 2) return null
    var sum = 0.0
    for (v in values) sum += (v - mean) * (v - mean)
    return sqrt(sum / (values.size - 1))
}

/** Throws [IllegalArgumentException] naming [what] when [values] holds NaN or ±∞. */
internal fun requireFinite(values: List<Double>, what: String) {
    val bad = values.indexOfFirst { !it.isFinite() }
    require(bad < 0) { "$what value ${bad + 1} is ${values[bad]}; responses must be finite numbers" }
}
