package org.hapticon.core.render

import org.hapticon.core.signal.SampleClock
import org.hapticon.core.signal.cosineOfCycles
import org.hapticon.core.signal.sineOfCycles

/**
 * FAST mode's carrier × envelope kernel: four phasors for four consecutive samples, each rotated by four
 * sample steps per iteration. A single rotating phasor is one long dependency chain (each sample waits
 * for the previous multiply-add, ~8 cycles), so it runs at ~400 M samples/s whatever the CPU's width;
 * four independent chains keep the multipliers busy and reach ~1 G samples/s per thread.
 *
 * The envelope is consumed as the current run of the shared envelope engine gives it
 * ([runValue] of its two lines at the run-relative index m; see [EnvelopeSweep]), with m an exact whole
 * number in double, so FAST's envelope is EXACT's bit for bit: only the carrier differs.
 *
 * Output is independent of how reads are split: sample A + 4q + l (A an anchor, l < 4) is always lane l
 * set at the anchor and rotated q times; a partial group of four only relabels lanes ([shift]).
 *
 * Error: lanes are set from the exact phase at each anchor (every [IconSynthesizer.FAST_ANCHOR_INTERVAL]
 * samples), lane l by l single-step rotations, then up to interval/4 four-step rotations: the phasor's
 * rounding stays ~1e-13, far below one float32 step (5.96e-8), at any note, rate and stream position.
 */
internal class InterleavedPhasor(clock: SampleClock) {
    // One-sample and four-sample rotations, from the exact step in cycles (reduced to [0, 1)).
    private val stepCycles = clock.frequency / clock.sampleRate
    private val stepCos = cosineOfCycles(stepCycles)
    private val stepSin = sineOfCycles(stepCycles)
    private val quadCycles = (4.0 * stepCycles).let { it - Math.floor(it) }
    private val quadCos = cosineOfCycles(quadCycles)
    private val quadSin = sineOfCycles(quadCycles)

    // Lane l holds cis(2π · phase) of the sample l after the next one.
    private var c0 = 1.0; private var s0 = 0.0
    private var c1 = 1.0; private var s1 = 0.0
    private var c2 = 1.0; private var s2 = 0.0
    private var c3 = 1.0; private var s3 = 0.0

    /** Sets the lanes so the next sample has phase [cycles] (exact, in [0, 1)). */
    fun anchor(cycles: Double) {
        c0 = cosineOfCycles(cycles); s0 = sineOfCycles(cycles)
        c1 = c0 * stepCos - s0 * stepSin; s1 = s0 * stepCos + c0 * stepSin
        c2 = c1 * stepCos - s1 * stepSin; s2 = s1 * stepCos + c1 * stepSin
        c3 = c2 * stepCos - s2 * stepSin; s3 = s2 * stepCos + c2 * stepSin
    }

    /**
     * Writes [count] samples runValue(rv, rsl, fv, fsl, m + j) · sin(phase j) into [destination] from
     * [offset] as doubles, and advances the lanes past them.
     */
    fun fill(destination: DoubleArray, offset: Int, count: Int, rv: Double, rsl: Double, fv: Double, fsl: Double, m: Double) {
        when (dominantLine(count, rv, rsl, fv, fsl, m)) {
            RISING -> kernel(count, m, { rv + rsl * it }) { j, value -> destination[offset + j] = value }
            FALLING -> kernel(count, m, { fv + fsl * it }) { j, value -> destination[offset + j] = value }
            else -> kernel(count, m, { runValue(rv, rsl, fv, fsl, it) }) { j, value -> destination[offset + j] = value }
        }
    }

    /** As [fill], narrowing each double sample to float32 as it is written (no scratch pass). */
    fun fill(destination: FloatArray, offset: Int, count: Int, rv: Double, rsl: Double, fv: Double, fsl: Double, m: Double) {
        when (dominantLine(count, rv, rsl, fv, fsl, m)) {
            RISING -> kernel(count, m, { rv + rsl * it }) { j, value -> destination[offset + j] = value.toFloat() }
            FALLING -> kernel(count, m, { fv + fsl * it }) { j, value -> destination[offset + j] = value.toFloat() }
            else -> kernel(count, m, { runValue(rv, rsl, fv, fsl, it) }) { j, value -> destination[offset + j] = value.toFloat() }
        }
    }

    /**
     * Which single line gives runValue over the whole chunk, bit for bit, or [BOTH]. Evaluating one line
     * instead of two and their max halves the kernel's work (1.6 vs 0.8 G samples/s). A line qualifies when
     * runValue equals it at both ends of the chunk and the other line lies below it by [MARGIN] there: both
     * are linear, so it then lies below throughout, by far more than rounding (~1e-16), and runValue (the
     * max of the lines) returns exactly this line's value. (Were runValue ever a sum, equality at both ends
     * would need the other line to be zero there, or below rounding, hence so throughout.) The FAST vs
     * EXACT tests on overlapping icons hold this to EXACT's own envelope whatever runValue becomes.
     * A chunk where the lines cross (at most one per envelope corner) takes the general kernel.
     */
    private fun dominantLine(count: Int, rv: Double, rsl: Double, fv: Double, fsl: Double, m: Double): Int {
        if (count < 8) return BOTH
        val last = m + (count - 1)
        val risingFirst = rv + rsl * m
        val risingLast = rv + rsl * last
        val fallingFirst = fv + fsl * m
        val fallingLast = fv + fsl * last
        val first = runValue(rv, rsl, fv, fsl, m)
        val end = runValue(rv, rsl, fv, fsl, last)
        return when {
            first == risingFirst && end == risingLast && fallingFirst < risingFirst - MARGIN && fallingLast < risingLast - MARGIN -> RISING
            first == fallingFirst && end == fallingLast && risingFirst < fallingFirst - MARGIN && risingLast < fallingLast - MARGIN -> FALLING
            else -> BOTH
        }
    }

    private inline fun kernel(count: Int, m: Double, envelope: (Double) -> Double, write: (Int, Double) -> Unit) {
        val qc = quadCos
        val qs = quadSin
        var a0 = c0; var b0 = s0
        var a1 = c1; var b1 = s1
        var a2 = c2; var b2 = s2
        var a3 = c3; var b3 = s3
        var m0 = m
        // A counted loop on the array index itself, so the JIT can drop the per-store range checks.
        val whole = count and 3.inv()
        var j = 0
        while (j < whole) {
            write(j, envelope(m0) * b0)
            write(j + 1, envelope(m0 + 1.0) * b1)
            write(j + 2, envelope(m0 + 2.0) * b2)
            write(j + 3, envelope(m0 + 3.0) * b3)
            val n0 = a0 * qc - b0 * qs; b0 = b0 * qc + a0 * qs; a0 = n0
            val n1 = a1 * qc - b1 * qs; b1 = b1 * qc + a1 * qs; a1 = n1
            val n2 = a2 * qc - b2 * qs; b2 = b2 * qc + a2 * qs; a2 = n2
            val n3 = a3 * qc - b3 * qs; b3 = b3 * qc + a3 * qs; a3 = n3
            m0 += 4.0
            j += 4
        }
        c0 = a0; s0 = b0; c1 = a1; s1 = b1; c2 = a2; s2 = b2; c3 = a3; s3 = b3
        val rest = count - j
        if (rest > 0) {
            write(j, envelope(m0) * s0)
            if (rest > 1) write(j + 1, envelope(m0 + 1.0) * s1)
            if (rest > 2) write(j + 2, envelope(m0 + 2.0) * s2)
            shift(rest)
        }
    }

    /** After [used] (1..3) samples of a group: lane l becomes old lane used + l, rotated once when that wraps. */
    private fun shift(used: Int) {
        val qc = quadCos
        val qs = quadSin
        // Old lanes l < used are spent; rotated by four steps they become the lanes after old lane 3.
        val r0c = c0 * qc - s0 * qs; val r0s = s0 * qc + c0 * qs
        val r1c = c1 * qc - s1 * qs; val r1s = s1 * qc + c1 * qs
        val r2c = c2 * qc - s2 * qs; val r2s = s2 * qc + c2 * qs
        when (used) {
            1 -> { c0 = c1; s0 = s1; c1 = c2; s1 = s2; c2 = c3; s2 = s3; c3 = r0c; s3 = r0s }
            2 -> { c0 = c2; s0 = s2; c1 = c3; s1 = s3; c2 = r0c; s2 = r0s; c3 = r1c; s3 = r1s }
            3 -> { c0 = c3; s0 = s3; c1 = r0c; s1 = r0s; c2 = r1c; s2 = r1s; c3 = r2c; s3 = r2s }
        }
    }

    private companion object {
        const val BOTH = 0
        const val RISING = 1
        const val FALLING = 2

        /** How far below the other line must lie at both chunk ends for one line to stand for runValue. */
        const val MARGIN = 1e-12
    }
}
