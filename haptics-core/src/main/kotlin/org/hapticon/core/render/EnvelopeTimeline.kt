package org.hapticon.core.render

import org.hapticon.core.HapticIcon

/**
 * The whole-icon envelope at sample resolution, as consecutive runs covering [0, sampleCount): the icon's
 * [EnvelopeShape] placed at every onset, which every renderer samples ([IconRenderer] and [PcmRenderer]
 * sample by sample, [HapticIcon.envelope] — and through it [VibrationWaveform], [EnvelopeControlPoints]
 * and the plots — in continuous time via [valueAtTime]).
 *
 * Repetition k starts at sample onset(k) = round(k · period · fs), which never decreases with k, and
 * follows the pieces of [envelopeSegments] from there. Overlapping repetitions combine per the model:
 * PAPER by maximum, PROCESSING by sum (JSyn's `InputMixingBlockPart.getValues` adds every output
 * connected to an input port, and Processing Sound 2.0.1–2.3.1's `Env.play` never disconnects the
 * previous repetition's reader; see [ProcessingEnvelope]).
 *
 * A run is a stretch [start, end) over which the envelope is max(rising line, falling line) in
 * m = index − start ([runValue]), which is what the sample loop consumes. The run boundaries are 0,
 * sampleCount and every onset + segment boundary between them, so within a run no repetition
 * crosses a segment boundary and every repetition's value is a fixed line.
 *
 * SUM: the rising line is the sum of the lines of every repetition playing in the run and the falling
 * line is the zero line (harmless: the sum is never negative).
 *
 * MAX: every repetition rises during its attack and never rises afterwards, so the maximum over all
 * repetitions is the maximum of two candidates: among repetitions in their attack the one furthest
 * in (smallest k), and among repetitions past it the one least far in (largest k). An absent line is
 * the zero line.
 *
 * Nothing is built up front. For each boundary d of one repetition (0, the attack's end, …, the
 * envelope's end; [offsets]) let count_d(t) = #{k : onset(k) + d ≤ t}, a pointer into the sorted
 * onsets. At a run start t the repetitions in their attack are k in [count_attack(t), count_0(t))
 * and those past it are k in [count_end(t), count_attack(t)): contiguous ranges, so the rising
 * candidate is k = count_attack(t), the falling one k = count_attack(t) − 1, and the playing ones
 * k in [count_end(t), count_0(t)). The next run starts at the smallest onset(count_d(t)) + d over all
 * d. An [EnvelopeSweep] moves the pointers forward as a stream advances (amortised O(1) per run, no
 * allocation); [valueAt] finds them by binary search for random access. Both evaluate a run with the
 * same code from the same start, so they agree bit for bit.
 */
internal class EnvelopeTimeline(icon: HapticIcon, model: EnvelopeModel, private val sampleRate: Int, val sampleCount: Long) {
    private val pieces: List<EnvelopeSegment> = envelopeSegments(icon, model, sampleRate)

    // An empty piece may carry a division by zero; it is never evaluated, so drop it here.
    private val segments: Array<EnvelopeSegment> = pieces.filter { it.endSample > it.firstSample }.toTypedArray()

    /** The pieces with a positive span in continuous time, for [valueAtTime]. */
    private val spans: Array<EnvelopeSegment> = pieces.filter { it.to > it.from }.toTypedArray()

    /** True when overlapping repetitions add (PROCESSING), false when the larger wins (PAPER): [EnvelopeShape.sums]. */
    val sums: Boolean = EnvelopeShape.of(icon, model).sums

    /** onset(k), non-decreasing in k. */
    private val onsets = LongArray(icon.count) { k -> Math.round(k * icon.period * sampleRate) }

    /** Number of repetitions. */
    val repetitions: Int get() = onsets.size

    /**
     * The distinct segment boundaries of one repetition relative to its onset, ascending: 0, then
     * each non-empty segment's end. Empty when one repetition has no samples at all.
     */
    val offsets: LongArray =
        if (segments.isEmpty()) LongArray(0) else LongArray(segments.size + 1) { j -> if (j == 0) 0L else segments[j - 1].endSample }

    /** Index into [offsets] of the attack's end: 1, or 0 when there is no attack (nothing ever rises). */
    val attackOffset: Int = if (segments.isNotEmpty() && segments[0].rising) 1 else 0

    /** Index into [offsets] of the envelope's end. */
    val endOffset: Int = offsets.size - 1

    /** onset([k]) + offsets[[j]]: boundary [j] of repetition [k]. */
    fun boundary(k: Int, j: Int): Long = onsets[k] + offsets[j]

    /**
     * The envelope at sample [index] (0 ≤ index < sampleCount), by random access: binary searches
     * find the run holding [index], which is then evaluated exactly as [EnvelopeSweep] does. Does
     * not allocate.
     */
    fun valueAt(index: Long): Double {
        if (offsets.isEmpty()) return 0.0
        // The run starts at the last boundary at or before index. No boundary lies in (start, index],
        // so the counts at index are the counts at start.
        var start = 0L
        var started = 0
        var attacking = 0
        var ended = 0
        for (j in offsets.indices) {
            val count = countAtOrBefore(index - offsets[j])
            if (count > 0) start = maxOf(start, boundary(count - 1, j))
            if (j == 0) started = count
            if (j == attackOffset) attacking = count
            if (j == endOffset) ended = count
        }
        if (sums) return runValue(sumOfValues(ended, started, start), sumOfSlopes(ended, started, start), 0.0, 0.0, (index - start).toDouble())
        val rising = risingRepetition(started, attacking)
        val falling = fallingRepetition(attacking, ended)
        return runValue(
            if (rising < 0) 0.0 else lineValue(rising, start),
            if (rising < 0) 0.0 else lineSlope(rising, start),
            if (falling < 0) 0.0 else lineValue(falling, start),
            if (falling < 0) 0.0 else lineSlope(falling, start),
            (index - start).toDouble(),
        )
    }

    /**
     * The rising candidate at a run start where [started] onsets have passed and [attacking] attacks
     * have ended (both count_d of that start): repetition [attacking], or -1 if none is in its attack.
     */
    fun risingRepetition(started: Int, attacking: Int): Int = if (attacking < started) attacking else -1

    /** The falling candidate (see [risingRepetition]; [ended] envelopes have ended): repetition attacking − 1, or -1. */
    fun fallingRepetition(attacking: Int, ended: Int): Int = if (attacking > ended) attacking - 1 else -1

    /** Repetition [k]'s value at sample [start], where it lies inside one of its segments. */
    fun lineValue(k: Int, start: Long): Double {
        val n = start - onsets[k]
        return segmentAt(n).valueAt(n)
    }

    /** Repetition [k]'s slope per sample at [start], where it lies inside one of its segments. */
    fun lineSlope(k: Int, start: Long): Double = segmentAt(start - onsets[k]).slope

    /** Σ lineValue(k, start) over the repetitions k in [from, until), in increasing k. */
    fun sumOfValues(from: Int, until: Int, start: Long): Double {
        var sum = 0.0
        for (k in from until until) sum += lineValue(k, start)
        return sum
    }

    /** Σ lineSlope(k, start) over the repetitions k in [from, until), in increasing k. */
    fun sumOfSlopes(from: Int, until: Int, start: Long): Double {
        var sum = 0.0
        for (k in from until until) sum += lineSlope(k, start)
        return sum
    }

    /**
     * The envelope at [seconds] in continuous time: each playing repetition's piece evaluated at the
     * fractional position seconds · fs after its onset (PAPER's exact trapezoid; PROCESSING's reader
     * lines, exact at every sample and straight between), combined as the samples are. 0 outside
     * [0, sampleCount / fs) and for a non-finite time.
     */
    fun valueAtTime(seconds: Double): Double {
        if (spans.isEmpty() || !seconds.isFinite()) return 0.0
        val x = seconds * sampleRate
        if (x < 0.0 || x >= sampleCount) return 0.0
        val spanEnd = spans.last().to
        var result = 0.0
        // Onsets are whole samples, so onset ≤ x exactly when onset ≤ floor(x); older repetitions end first.
        var k = countAtOrBefore(Math.floor(x).toLong()) - 1
        while (k >= 0) {
            val local = x - onsets[k]
            if (local >= spanEnd) break
            val value = spanAt(local).valueAt(local)
            result = if (sums) result + value else maxOf(result, value)
            k--
        }
        return result
    }

    private fun spanAt(local: Double): EnvelopeSegment {
        for (span in spans) if (local < span.to) return span
        return spans.last()
    }

    /** How many onsets are ≤ [t]. */
    private fun countAtOrBefore(t: Long): Int {
        var low = 0
        var high = onsets.size
        while (low < high) {
            val mid = (low + high) ushr 1
            if (onsets[mid] <= t) low = mid + 1 else high = mid
        }
        return low
    }

    /** The segment holding repetition-local sample [n], 0 ≤ n < the envelope's end. */
    private fun segmentAt(n: Long): EnvelopeSegment {
        for (segment in segments) if (n < segment.endSample) return segment
        throw IllegalStateException("sample $n is outside one envelope")
    }
}

/** The envelope m samples into a run: the one formula the stream and random access both use. */
@Suppress("NOTHING_TO_INLINE")
internal inline fun runValue(risingValue: Double, risingSlope: Double, fallingValue: Double, fallingSlope: Double, m: Double): Double =
    Math.max(risingValue + risingSlope * m, fallingValue + fallingSlope * m)

/**
 * The runs of a [timeline] in order, from the one starting at sample 0, for one stream: holds the
 * current run's [start], [end] and lines, and moves to the next run by advancing one pointer per
 * segment boundary over the sorted onsets. Allocates only at construction.
 */
internal class EnvelopeSweep(private val timeline: EnvelopeTimeline) {
    /** count_d(start) for each boundary d = timeline.offsets[j] (see [EnvelopeTimeline]). */
    private val counts = IntArray(timeline.offsets.size)

    var start: Long = 0
        private set
    var end: Long = 0
        private set
    var risingValue: Double = 0.0
        private set
    var risingSlope: Double = 0.0
        private set
    var fallingValue: Double = 0.0
        private set
    var fallingSlope: Double = 0.0
        private set

    init {
        load(0L)
    }

    /** Moves to the run that starts at the current [end]; call only while end < sampleCount. */
    fun advance() {
        load(end)
    }

    private fun load(runStart: Long) {
        val t = timeline
        var next = t.sampleCount
        for (j in counts.indices) {
            var count = counts[j]
            while (count < t.repetitions && t.boundary(count, j) <= runStart) count++
            counts[j] = count
            if (count < t.repetitions) next = minOf(next, t.boundary(count, j))
        }
        start = runStart
        end = next
        if (counts.isEmpty()) {
            risingValue = 0.0; risingSlope = 0.0; fallingValue = 0.0; fallingSlope = 0.0
            return
        }
        val attacking = counts[t.attackOffset]
        if (t.sums) {
            risingValue = t.sumOfValues(counts[t.endOffset], counts[0], runStart)
            risingSlope = t.sumOfSlopes(counts[t.endOffset], counts[0], runStart)
            fallingValue = 0.0; fallingSlope = 0.0
            return
        }
        val rising = t.risingRepetition(counts[0], attacking)
        val falling = t.fallingRepetition(attacking, counts[t.endOffset])
        risingValue = if (rising < 0) 0.0 else t.lineValue(rising, runStart)
        risingSlope = if (rising < 0) 0.0 else t.lineSlope(rising, runStart)
        fallingValue = if (falling < 0) 0.0 else t.lineValue(falling, runStart)
        fallingSlope = if (falling < 0) 0.0 else t.lineSlope(falling, runStart)
    }
}
