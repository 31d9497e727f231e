package org.hapticon.gesture.extraction

import kotlin.math.sqrt

/**
 * A trapezoid fitted to one repetition's envelope: 0 before [start], a line up to [level] at [attackEnd],
 * flat to [sustainEnd], a line down to 0 at [releaseEnd], 0 after. Breakpoints are sample indices into the
 * fitted array; [level] is in the envelope's units.
 */
public class Trapezoid(
    /** Index where the attack ramp starts. */
    public val start: Int,
    /** Index where the attack ends and the sustain begins. */
    public val attackEnd: Int,
    /** Index where the sustain ends and the release begins. */
    public val sustainEnd: Int,
    /** Index where the release reaches 0. */
    public val releaseEnd: Int,
    /** Sustain amplitude, least-squares optimal for these breakpoints, >= 0. */
    public val level: Double,
    /** Root mean square of the residual over the fitted span. */
    public val rmsError: Double,
    /** Coefficient of determination over the fitted span (1 = perfect; 0 when the span is flat). */
    public val rSquared: Double,
) {
    /** The model's value at index [i]. */
    public fun valueAt(i: Int): Double = level * PiecewiseLinearFit.shape(i.toDouble(), start, attackEnd, sustainEnd, releaseEnd)

    override fun toString(): String = "Trapezoid($start, $attackEnd, $sustainEnd, $releaseEnd, level=$level, rms=$rmsError, r2=$rSquared)"
}

/**
 * Segmented least squares with three breakpoints and zero ends: finds the [Trapezoid] closest (in squared
 * error) to an envelope. For fixed breakpoints the model is `level · shape`, linear in level, so the best
 * level and the error come in closed form; prefix sums of y, i·y and y² make that O(1) per candidate.
 * The breakpoints are then found by coordinate descent — each one in turn moved to its best position
 * between its neighbours (an O(n) scan) until none moves — started from threshold crossings, which on a
 * trapezoid-like envelope are already near the optimum.
 */
public object PiecewiseLinearFit {
    /**
     * Fits [envelope] (at least 2 finite samples). Throws [IllegalArgumentException] for a shorter or
     * non-finite envelope.
     */
    public fun fit(envelope: DoubleArray): Trapezoid {
        val n = envelope.size
        require(n >= 2) { "need at least 2 envelope samples to fit, got $n" }
        require(envelope.all { it.isFinite() }) { "envelope holds a non-finite value" }
        val sums = PrefixSums(envelope)
        val b = initialBreakpoints(envelope)
        var best = sums.score(b[0], b[1], b[2], b[3])
        for (iteration in 0 until MAX_ITERATIONS) {
            var moved = false
            for (which in 0 until 4) {
                val lo = if (which == 0) 0 else b[which - 1]
                val hi = if (which == 3) n else b[which + 1]
                val was = b[which]
                var bestAt = was
                for (candidate in lo..hi) {
                    b[which] = candidate
                    val score = sums.score(b[0], b[1], b[2], b[3])
                    if (score > best + 1e-12 * (1.0 + best)) {
                        best = score
                        bestAt = candidate
                    }
                }
                b[which] = bestAt
                if (bestAt != was) moved = true
            }
            if (!moved) break
        }
        sums.project(b[0], b[1], b[2], b[3])
        val sy = sums.shapeDotY
        val ss = sums.shapeSquares
        val level = if (ss > 0.0 && sy > 0.0) sy / ss else 0.0
        val sse = maxOf(0.0, sums.totalSquares - level * sy)
        val mean = sums.total / n
        val sst = maxOf(0.0, sums.totalSquares - n * mean * mean)
        return Trapezoid(
            b[0], b[1], b[2], b[3], level,
            rmsError = sqrt(sse / n),
            rSquared = if (sst > 0.0) 1.0 - sse / sst else 0.0,
        )
    }

    private const val MAX_ITERATIONS = 50

    /** Start: where the envelope leaves 5 % of its maximum, reaches 90 %, last holds 90 %, and falls back to 5 %. */
    private fun initialBreakpoints(y: DoubleArray): IntArray {
        val n = y.size
        var peak = 0
        for (i in y.indices) if (y[i] > y[peak]) peak = i
        val high = 0.9 * y[peak]
        val low = 0.05 * y[peak]
        var attackEnd = peak
        while (attackEnd > 0 && y[attackEnd - 1] >= high) attackEnd--
        var start = attackEnd
        while (start > 0 && y[start - 1] > low) start--
        var sustainEnd = peak
        while (sustainEnd < n - 1 && y[sustainEnd + 1] >= high) sustainEnd++
        var releaseEnd = sustainEnd + 1
        while (releaseEnd < n && y[releaseEnd] > low) releaseEnd++
        return intArrayOf(start, attackEnd, sustainEnd, minOf(n, releaseEnd))
    }

    /** Unit trapezoid at continuous position [x]. */
    internal fun shape(x: Double, t0: Int, t1: Int, t2: Int, t3: Int): Double = when {
        x < t0 -> 0.0
        x < t1 -> (x - t0) / (t1 - t0)
        x < t2 -> 1.0
        x < t3 -> (t3 - x) / (t3 - t2)
        else -> 0.0
    }

    private class PrefixSums(y: DoubleArray) {
        private val p0 = DoubleArray(y.size + 1)
        private val p1 = DoubleArray(y.size + 1)
        val total: Double
        val totalSquares: Double

        /** Σ shape·y and Σ shape² of the last [project] call (fields, not a pair: the scan calls it per candidate). */
        var shapeDotY = 0.0
        var shapeSquares = 0.0

        init {
            var squares = 0.0
            for (i in y.indices) {
                p0[i + 1] = p0[i] + y[i]
                p1[i + 1] = p1[i] + i * y[i]
                squares += y[i] * y[i]
            }
            total = p0[y.size]
            totalSquares = squares
        }

        /** Sets [shapeDotY] and [shapeSquares] for breakpoints t0 <= t1 <= t2 <= t3. */
        fun project(t0: Int, t1: Int, t2: Int, t3: Int) {
            var sy = 0.0
            var ss = 0.0
            val ma = t1 - t0
            if (ma > 0) {
                // shape (i − t0)/ma for i in [t0, t1)
                sy += ((p1[t1] - p1[t0]) - t0 * (p0[t1] - p0[t0])) / ma
                ss += (ma - 1.0) * (2.0 * ma - 1.0) / (6.0 * ma)
            }
            sy += p0[t2] - p0[t1]
            ss += (t2 - t1).toDouble()
            val mr = t3 - t2
            if (mr > 0) {
                // shape (t3 − i)/mr for i in [t2, t3): values 1, (mr−1)/mr, …, 1/mr
                sy += (t3 * (p0[t3] - p0[t2]) - (p1[t3] - p1[t2])) / mr
                ss += (mr + 1.0) * (2.0 * mr + 1.0) / (6.0 * mr)
            }
            shapeDotY = sy
            shapeSquares = ss
        }

        /** (Σ shape·y)² / Σ shape² when positive: the error reduction the best level achieves; larger is better. */
        fun score(t0: Int, t1: Int, t2: Int, t3: Int): Double {
            project(t0, t1, t2, t3)
            val sy = shapeDotY
            val ss = shapeSquares
            return if (ss > 0.0 && sy > 0.0) sy * sy / ss else 0.0
        }
    }
}
