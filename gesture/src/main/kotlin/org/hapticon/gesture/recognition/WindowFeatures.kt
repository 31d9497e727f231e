package org.hapticon.gesture.recognition

import kotlin.math.ln
import kotlin.math.sqrt

/**
 * The 33 features of one channel over one window: 11 statistics ([STATISTICS]) of the samples, of their
 * first derivative and of their second derivative, in that order (`force.mean`, …, `force.d1.mean`, …).
 *
 * The statistics, over the n values of a series:
 * - `sum`, `max`, `min`, `mean`;
 * - `median` (mean of the two middle values when n is even);
 * - `std` and `variance`: population form, dividing by n;
 * - `area`: the trapezoid integral over time, in unit·s (samples 1/sampleRate apart; 0 for one value);
 * - `iqr`: Q3 − Q1, quartiles by linear interpolation between order statistics (numpy's default);
 * - `peaks`: the number of peaks with prominence ≥ [PEAK_PROMINENCE] × (max − min) of the series — a
 *   hysteresis rule: a peak counts once the series has risen at least that much above the lowest value
 *   since the previous peak and then fallen at least that much below it (a peak cut by the window end is not
 *   counted), so a flat or constant series has none and noise riding on a plateau adds none;
 * - `entropy`: Shannon entropy in bits of a histogram of [ENTROPY_BINS] equal-width bins spanning
 *   [min, max] of the series (0 for a constant series, at most log2 [ENTROPY_BINS]).
 *
 * Derivatives are finite differences times the sample rate (unit/s and unit/s²), so a window of n samples
 * has n − 1 and n − 2 derivative values; a series with no values (a one- or two-sample window) gives all
 * zeros. Non-finite samples (a sensor gap) are replaced by the last finite sample of the window before them
 * (the first finite one when the window starts with a gap, 0 when there is none); samples beyond
 * ±[SAMPLE_LIMIT] are clipped to it. So no feature is ever NaN or infinite.
 *
 * One extractor holds scratch arrays for windows of up to [maxFrames] samples and allocates nothing per call;
 * it is not thread-safe.
 */
public class WindowFeatures(
    /** Samples per second; finite and > 0. */
    public val sampleRate: Double,
    /** The longest window [extract] accepts. */
    public val maxFrames: Int,
) {
    init {
        require(sampleRate.isFinite() && sampleRate > 0.0) { "sample rate must be finite and > 0 Hz, was $sampleRate" }
        require(maxFrames >= 1) { "windows need at least one frame, maxFrames was $maxFrames" }
    }

    private val series = DoubleArray(maxFrames)
    private val derivative = DoubleArray(maxFrames)
    private val sorted = DoubleArray(maxFrames)
    private val bins = IntArray(ENTROPY_BINS)

    /**
     * Writes the [PER_CHANNEL] features of `samples[from until from + count]` into `out[outOffset ...]`.
     * [IllegalArgumentException] when [count] is outside 1..[maxFrames] or the ranges do not fit.
     */
    public fun extract(samples: DoubleArray, from: Int, count: Int, out: DoubleArray, outOffset: Int) {
        require(count in 1..maxFrames) { "window of $count frames is outside 1..$maxFrames" }
        require(from >= 0 && from + count <= samples.size) { "window [$from, ${from + count}) is outside 0..${samples.size}" }
        require(outOffset >= 0 && outOffset + PER_CHANNEL <= out.size) { "no room for $PER_CHANNEL features at $outOffset in ${out.size}" }
        cleanInto(samples, from, count)
        statistics(series, count, out, outOffset)
        var n = count
        for (order in 1..2) {
            // In place: each difference only reads the value after the one it overwrites.
            val source = if (order == 1) series else derivative
            for (i in 0 until n - 1) derivative[i] = (source[i + 1] - source[i]) * sampleRate
            n = maxOf(n - 1, 0)
            statistics(derivative, n, out, outOffset + order * STATISTICS.size)
        }
    }

    private fun cleanInto(samples: DoubleArray, from: Int, count: Int) {
        var held = 0.0
        for (i in from until from + count) {
            if (samples[i].isFinite()) { held = samples[i]; break }
        }
        for (i in 0 until count) {
            val x = samples[from + i]
            if (x.isFinite()) held = x.coerceIn(-SAMPLE_LIMIT, SAMPLE_LIMIT)
            series[i] = held
        }
    }

    private fun statistics(values: DoubleArray, n: Int, out: DoubleArray, at: Int) {
        if (n == 0) {
            out.fill(0.0, at, at + STATISTICS.size)
            return
        }
        var sum = 0.0
        var max = values[0]
        var min = values[0]
        for (i in 0 until n) {
            val x = values[i]
            sum += x
            if (x > max) max = x
            if (x < min) min = x
        }
        val mean = sum / n
        var squares = 0.0
        for (i in 0 until n) {
            val d = values[i] - mean
            squares += d * d
        }
        val variance = squares / n
        var area = 0.0
        for (i in 0 until n - 1) area += (values[i] + values[i + 1]) * 0.5
        area /= sampleRate
        values.copyInto(sorted, 0, 0, n)
        sorted.sort(0, n)
        out[at] = sum
        out[at + 1] = max
        out[at + 2] = min
        out[at + 3] = mean
        out[at + 4] = quantile(n, 0.5)
        out[at + 5] = sqrt(variance)
        out[at + 6] = variance
        out[at + 7] = area
        out[at + 8] = quantile(n, 0.75) - quantile(n, 0.25)
        out[at + 9] = peaks(values, n, (max - min) * PEAK_PROMINENCE).toDouble()
        out[at + 10] = entropy(values, n, min, max)
    }

    /** Linear interpolation between order statistics at position q·(n − 1) of the sorted scratch. */
    private fun quantile(n: Int, q: Double): Double {
        val position = q * (n - 1)
        val lower = position.toInt()
        val fraction = position - lower
        return if (lower + 1 >= n) sorted[lower] else sorted[lower] + (sorted[lower + 1] - sorted[lower]) * fraction
    }

    private fun peaks(values: DoubleArray, n: Int, prominence: Double): Int {
        if (prominence <= 0.0) return 0
        var count = 0
        var trough = values[0]
        var top = values[0]
        var rising = true
        for (i in 1 until n) {
            val x = values[i]
            if (rising) {
                if (x > top) top = x
                if (top - trough >= prominence && top - x >= prominence) {
                    count++
                    rising = false
                    trough = x
                } else if (x < trough) {
                    trough = x
                    top = x
                }
            } else {
                if (x < trough) trough = x
                if (x - trough >= prominence) {
                    rising = true
                    top = x
                }
            }
        }
        return count
    }

    private fun entropy(values: DoubleArray, n: Int, min: Double, max: Double): Double {
        val range = max - min
        if (range <= 0.0 || n < 2) return 0.0
        bins.fill(0)
        for (i in 0 until n) {
            val bin = ((values[i] - min) / range * ENTROPY_BINS).toInt().coerceAtMost(ENTROPY_BINS - 1)
            bins[bin]++
        }
        var bits = 0.0
        for (c in bins) {
            if (c == 0) continue
            val p = c.toDouble() / n
            bits -= p * ln(p)
        }
        return bits / LN2
    }

    public companion object {
        /** The statistics computed on each series, in output order. */
        public val STATISTICS: List<String> =
            listOf("sum", "max", "min", "mean", "median", "std", "variance", "area", "iqr", "peaks", "entropy")

        /** Features per channel: [STATISTICS] on the samples, the first and the second derivative. */
        public val PER_CHANNEL: Int = 3 * STATISTICS.size

        /** A peak must stand out by this fraction of the series' range (max − min) on both sides. */
        public const val PEAK_PROMINENCE: Double = 0.2

        /** Histogram bins of the entropy feature. */
        public const val ENTROPY_BINS: Int = 16

        /** Samples are clipped to ±this, far beyond any force (N) or acceleration (g), so sums cannot overflow. */
        public const val SAMPLE_LIMIT: Double = 1e9

        private val LN2 = ln(2.0)

        /** Feature names for [channels] in output order, e.g. `force.max`, `force.d1.max`, `force.d2.max`. */
        public fun names(channels: List<String>): List<String> = channels.flatMap { channel ->
            listOf("", ".d1", ".d2").flatMap { series -> STATISTICS.map { "$channel$series.$it" } }
        }
    }
}
