package org.hapticon.core.render

import org.hapticon.core.HapticIcon

/**
 * A stretch of samples [start, end) over which the icon envelope is the larger of two lines in
 * m = index − start: a rising line (the oldest repetition still in its attack) and a falling line
 * (the youngest repetition past its attack). An absent line is the zero line, which is harmless
 * under max because envelopes are never negative.
 */
internal class EnvelopeRun(
    val start: Long,
    val end: Long,
    val risingValue: Double,
    val risingSlope: Double,
    val fallingValue: Double,
    val fallingSlope: Double,
) {
    /** The envelope at index start + [m]; the stream and random access both call this, so they agree bit for bit. */
    fun valueAt(m: Double): Double = Math.max(risingValue + risingSlope * m, fallingValue + fallingSlope * m)
}

/**
 * The whole-icon envelope at sample resolution, as consecutive [EnvelopeRun]s covering
 * [0, sampleCount).
 *
 * Repetition k starts at sample round(k · period · fs). Every repetition rises during its attack
 * and never rises afterwards, so the maximum over all repetitions is the maximum of two
 * candidates: among repetitions in their attack the one furthest in (smallest k), and among
 * repetitions past it the one least far in (largest k). Within a run no repetition crosses a
 * segment boundary, so both candidates are fixed lines.
 */
internal class EnvelopeTimeline(icon: HapticIcon, model: EnvelopeModel, sampleRate: Int, val sampleCount: Long) {
    private val segments = envelopeSegments(icon, model, sampleRate)
    private val onsets = LongArray(icon.count) { k -> Math.round(k * icon.period * sampleRate) }

    val runs: Array<EnvelopeRun> = buildRuns()

    /** Index into [runs] of the run holding sample [index] (0 ≤ index < sampleCount). */
    fun runIndexOf(index: Long): Int {
        var low = 0
        var high = runs.size - 1
        while (low < high) {
            val mid = (low + high + 1) ushr 1
            if (runs[mid].start <= index) low = mid else high = mid - 1
        }
        return low
    }

    /** The envelope at sample [index] (0 ≤ index < sampleCount). */
    fun valueAt(index: Long): Double {
        val run = runs[runIndexOf(index)]
        return run.valueAt((index - run.start).toDouble())
    }

    private fun buildRuns(): Array<EnvelopeRun> {
        if (sampleCount == 0L) return emptyArray()
        val boundaries = sortedSetOf(0L, sampleCount)
        for (onset in onsets) {
            for (segment in segments) {
                boundaries += onset + segment.firstSample
                boundaries += onset + segment.endSample
            }
        }
        val cuts = boundaries.filter { it in 0..sampleCount }
        return Array(cuts.size - 1) { i -> runAt(cuts[i], cuts[i + 1]) }
    }

    private fun runAt(start: Long, end: Long): EnvelopeRun {
        var rising: EnvelopeSegment? = null
        var risingOnset = 0L
        var falling: EnvelopeSegment? = null
        var fallingOnset = 0L
        for (k in onsets.indices) {
            val segment = segmentAt(start - onsets[k]) ?: continue
            if (segment.rising) {
                if (rising == null) { rising = segment; risingOnset = onsets[k] }
            } else {
                falling = segment
                fallingOnset = onsets[k]
            }
        }
        return EnvelopeRun(
            start = start,
            end = end,
            risingValue = rising?.valueAt(start - risingOnset) ?: 0.0,
            risingSlope = rising?.slope ?: 0.0,
            fallingValue = falling?.valueAt(start - fallingOnset) ?: 0.0,
            fallingSlope = falling?.slope ?: 0.0,
        )
    }

    private fun segmentAt(n: Long): EnvelopeSegment? =
        segments.firstOrNull { n >= it.firstSample && n < it.endSample }
}
