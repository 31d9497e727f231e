package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import kotlin.math.ceil

/**
 * A vibration for Android 16's envelope effects (`VibrationEffect.WaveformEnvelopeBuilder`, API 36): the
 * amplitude starts at 0 and ramps linearly to each [Point] in turn over that point's duration.
 *
 * [fit] approximates an envelope by straight segments whose ends lie on the envelope (segmented least
 * squares): among knot times on a millisecond grid it picks, by dynamic programming, the knots that
 * minimise the squared error over the envelope sampled every millisecond, subject to every segment lasting
 * at least `minSegmentMillis` (the platform minimum, 20 ms) and at most `maxPoints` points. The first segment
 * starts at amplitude 0, the last point has amplitude 0 and ends at the duration rounded to whole
 * milliseconds. It then uses the fewest points that do as well as the best. For example hug (1.5 s ramp to
 * 0.5, hold 1 s, 0.5 s down) becomes exactly (0.5, 1500 ms), (0.5, 1000 ms), (0.0, 500 ms).
 *
 * Envelopes with features shorter than the minimum segment cannot be followed: knock's 20 ms pulses every
 * 270 ms come out far too weak and wide. [fidelity] says so honestly, and [isRepresentable] lets the app
 * choose [VibrationWaveform] instead.
 */
public class EnvelopeControlPoints private constructor(
    /** The control points in order; empty when the envelope is shorter than one minimum segment. */
    public val points: List<Point>,
    /** How closely the ramps follow the ideal envelope, sampled every 0.1 ms. */
    public val fidelity: Fidelity,
    /** RMS error divided by the ideal envelope's RMS (0 = exact); infinite for a silent envelope rendered non-silent. */
    public val relativeRmsError: Double,
) {
    /** Sum of the point durations: the envelope duration rounded to whole milliseconds, or 0 without points. */
    public val totalMillis: Long get() = points.sumOf { it.durationMillis }

    /**
     * True when the points follow the envelope within [REPRESENTABLE_RELATIVE_ERROR]; when false the app
     * should play the icon with another renderer.
     */
    public val isRepresentable: Boolean get() = points.isNotEmpty() && relativeRmsError <= REPRESENTABLE_RELATIVE_ERROR

    /** A debug representation listing the points and the fidelity. */
    override fun toString(): String = "EnvelopeControlPoints(points=$points, fidelity=$fidelity)"

    /**
     * One control point, for `WaveformEnvelopeBuilder.addControlPoint(amplitude, frequencyHz, durationMillis)`.
     *
     * @property amplitude the amplitude reached at the end of the ramp, in [0, 1].
     * @property frequencyHz the carrier frequency at this point.
     * @property durationMillis how long the linear ramp from the previous point takes, at least the minimum segment.
     */
    public data class Point(val amplitude: Double, val frequencyHz: Double, val durationMillis: Long)

    public companion object {
        /** Default point budget: the control-point capacity commonly reported by API 36 devices. */
        public const val DEFAULT_MAX_POINTS: Int = 16

        /** Shortest ramp the platform accepts between control points, in milliseconds. */
        public const val MIN_SEGMENT_MILLIS: Int = 20

        /** Largest point budget [fit] accepts; it bounds the work and memory of the fit. */
        public const val MAX_POINTS_LIMIT: Int = 256

        /** Largest [relativeRmsError] for which [isRepresentable] is true. */
        public const val REPRESENTABLE_RELATIVE_ERROR: Double = 0.1

        /**
         * Approximates [icon]'s ideal envelope under [model] ([idealEnvelope]) with points at the icon's
         * carrier frequency, as described on [EnvelopeControlPoints].
         *
         * Throws [IllegalArgumentException] when the duration rounds to 0 ms, when [maxPoints] is not in
         * 1..[MAX_POINTS_LIMIT] or when [minSegmentMillis] < 1.
         */
        public fun fit(
            icon: HapticIcon,
            model: EnvelopeModel = EnvelopeModel.DEFAULT,
            maxPoints: Int = DEFAULT_MAX_POINTS,
            minSegmentMillis: Int = MIN_SEGMENT_MILLIS,
        ): EnvelopeControlPoints = fit(icon.idealEnvelope(model), icon.duration, icon.frequency, maxPoints, minSegmentMillis)

        /**
         * Approximates [envelope] (amplitude in [0, 1] at a time in seconds; values outside are clamped, NaN
         * reads as 0) over [durationSeconds] with at most [maxPoints] points at [frequencyHz], each segment at
         * least [minSegmentMillis] long, as described on [EnvelopeControlPoints].
         *
         * Throws [IllegalArgumentException] when the duration is not finite, rounds to 0 ms or exceeds
         * [HapticIcon.MAX_DURATION_SECONDS], when [frequencyHz] is not finite and > 0, when [maxPoints] is not
         * in 1..[MAX_POINTS_LIMIT] or when [minSegmentMillis] < 1.
         */
        public fun fit(
            envelope: (Double) -> Double,
            durationSeconds: Double,
            frequencyHz: Double,
            maxPoints: Int = DEFAULT_MAX_POINTS,
            minSegmentMillis: Int = MIN_SEGMENT_MILLIS,
        ): EnvelopeControlPoints {
            require(frequencyHz.isFinite() && frequencyHz > 0.0) { "frequencyHz must be finite and > 0, was $frequencyHz" }
            require(maxPoints in 1..MAX_POINTS_LIMIT) { "maxPoints must be in 1..$MAX_POINTS_LIMIT, was $maxPoints" }
            require(minSegmentMillis >= 1) { "minSegmentMillis must be >= 1, was $minSegmentMillis" }
            val ideal = EnvelopeCells(envelope, durationSeconds)
            val totalMillis = ideal.totalMillis
            if (totalMillis < minSegmentMillis) {
                val errors = ideal.errorsOf { 0.0 }
                val note = "no points: $totalMillis ms is shorter than one $minSegmentMillis ms segment; ${errors.summary()}"
                return EnvelopeControlPoints(emptyList(), Fidelity(errors.rms, errors.max, note), errors.relativeRms)
            }
            val knots = SegmentedLeastSquares(envelope, totalMillis, minSegmentMillis).bestKnots(maxPoints)
            val points = (1 until knots.size).map { i ->
                Point(knots[i].amplitude, frequencyHz, (knots[i].millis - knots[i - 1].millis).toLong())
            }
            var segment = 1
            val errors = ideal.errorsOf { cell ->
                val t = (cell + 0.5) / CELLS_PER_MILLI
                while (segment < knots.size && t > knots[segment].millis) segment++
                if (segment == knots.size) 0.0 else interpolate(knots[segment - 1], knots[segment], t)
            }
            val description = "${points.size} control points, segments ≥ $minSegmentMillis ms; ${errors.summary()}"
            return EnvelopeControlPoints(points, Fidelity(errors.rms, errors.max, description), errors.relativeRms)
        }

        private fun interpolate(from: Knot, to: Knot, millis: Double): Double =
            from.amplitude + (to.amplitude - from.amplitude) * (millis - from.millis) / (to.millis - from.millis)
    }
}

/** A corner of the piecewise-linear approximation. */
private class Knot(val millis: Int, val amplitude: Double)

/**
 * Segmented least squares over the envelope sampled at every millisecond 0..[totalMillis].
 *
 * Knots may sit on every millisecond of short envelopes; long ones use a coarser grid (at most
 * [MAX_GRID_KNOTS] times) plus the envelope's corners (where the slope changes), so the dynamic program
 * stays fast while piecewise-linear envelopes are still matched exactly.
 */
private class SegmentedLeastSquares(envelope: (Double) -> Double, private val totalMillis: Int, private val minSegment: Int) {
    private val samples = DoubleArray(totalMillis + 1) { safeAmplitude(envelope(it / 1000.0)) }

    // Prefix sums over samples[0 until i] of e, e² and m·e, for O(1) segment errors.
    private val sum = DoubleArray(totalMillis + 2)
    private val sumSquares = DoubleArray(totalMillis + 2)
    private val sumTimed = DoubleArray(totalMillis + 2)

    init {
        for (m in 0..totalMillis) {
            sum[m + 1] = sum[m] + samples[m]
            sumSquares[m + 1] = sumSquares[m] + samples[m] * samples[m]
            sumTimed[m + 1] = sumTimed[m] + m * samples[m]
        }
    }

    /** Knot times: start, end, a regular grid and the envelope's corners. */
    private val times: IntArray = run {
        val stride = ceil(totalMillis.toDouble() / MAX_GRID_KNOTS).toInt().coerceAtLeast(1)
        val chosen = sortedSetOf(0, totalMillis)
        for (m in 0..totalMillis step stride) chosen.add(m)
        val corners = (1 until totalMillis).filter {
            Math.abs(samples[it - 1] - 2 * samples[it] + samples[it + 1]) > CORNER_THRESHOLD
        }
        // A curved (not piecewise-linear) envelope has corners everywhere; then the grid alone must do.
        if (corners.size <= MAX_CORNER_KNOTS) chosen.addAll(corners)
        chosen.toIntArray()
    }

    /** The approximation starts and ends at 0; in between a knot lies on the envelope. */
    private fun knotValue(millis: Int): Double = if (millis == 0 || millis == totalMillis) 0.0 else samples[millis]

    /** Squared error of the straight line between knots at [from] and [to] over the samples strictly between. */
    private fun segmentError(from: Int, to: Int): Double {
        val n = to - from - 1
        if (n <= 0) return 0.0
        val start = knotValue(from)
        val slope = (knotValue(to) - start) / (to - from)
        // With d = m − from: Σ(e − start − slope·d)², expanded into the prefix sums.
        val sumE = sum[to] - sum[from + 1]
        val sumE2 = sumSquares[to] - sumSquares[from + 1]
        val sumDE = (sumTimed[to] - sumTimed[from + 1]) - from * sumE
        val sumD = n * (n + 1) / 2.0
        val sumD2 = n * (n + 1.0) * (2.0 * n + 1) / 6.0
        val error = sumE2 - 2 * start * sumE - 2 * slope * sumDE +
            n * start * start + 2 * start * slope * sumD + slope * slope * sumD2
        return maxOf(error, 0.0) // rounding can push an exact fit a hair below zero
    }

    /** The knots (start included) of the best fit with at most [maxSegments] segments. */
    fun bestKnots(maxSegments: Int): List<Knot> {
        val n = times.size
        val last = n - 1
        val row = maxSegments + 1
        // best[j·row + k]: least error reaching knot j with k segments; from[j·row + k]: the knot before j on
        // that path. Rows are per knot so that the inner loop over k walks memory in order.
        val best = DoubleArray(n * row) { Double.POSITIVE_INFINITY }
        val from = IntArray(n * row) { -1 }
        best[0] = 0.0
        // Each segment's error is computed once and reused for every segment count k.
        for (j in 1..last) {
            var i = 0
            while (i < j && times[j] - times[i] >= minSegment) {
                val error = segmentError(times[i], times[j])
                for (k in 1..maxSegments) {
                    val total = best[i * row + k - 1] + error
                    if (total < best[j * row + k]) {
                        best[j * row + k] = total
                        from[j * row + k] = i
                    }
                }
                i++
            }
        }
        // More points never fit worse, so take the fewest within a negligible margin of the best.
        val bestError = (1..maxSegments).minOf { best[last * row + it] }
        val segments = (1..maxSegments).first { best[last * row + it] <= bestError + SAME_ERROR_MARGIN * (totalMillis + 1) }
        val path = ArrayList<Knot>()
        var j = last
        for (k in segments downTo 1) {
            path.add(Knot(times[j], knotValue(times[j])))
            j = from[j * row + k]
        }
        path.add(Knot(0, 0.0))
        return path.asReversed()
    }

    private companion object {
        const val MAX_GRID_KNOTS = 1000
        const val MAX_CORNER_KNOTS = 1000
        const val CORNER_THRESHOLD = 1e-9
        /** Per-sample squared error below which two fits count as equally good. */
        const val SAME_ERROR_MARGIN = 1e-9
    }
}
