package org.hapticon.core.render

import org.hapticon.core.signal.SampleClock
import org.hapticon.core.signal.sineOfCycles

/**
 * The streaming engine behind [IconRenderer]: writes consecutive samples (envelope × carrier) as
 * doubles, starting at sample 0, with no allocation after construction. The envelope comes from an
 * [EnvelopeSweep], which finds each run only when the stream reaches it, so starting a stream costs
 * the same whatever the icon's length or repetition count.
 *
 * Carrier sample i has phase clock.cyclesAt(i + carrierOffset) (PROCESSING advances its phase
 * before each sample, so its offset is 1).
 *
 * EXACT: a sine of the exact phase at every sample, computed exactly like [IconRenderer.sampleAt].
 *
 * FAST: four interleaved rotating phasors ([InterleavedPhasor]), re-anchored from the exact phase at
 * every sample index that is a multiple of [FAST_ANCHOR_INTERVAL]. Anchors sit on a fixed grid of
 * indices, so the output does not depend on how reads are split into blocks; the phasors' own rounding
 * grows over at most one interval (~1e-13). Float reads get FAST samples narrowed in the kernel itself
 * ([fillFloats]), with no double scratch pass. Against EXACT in double precision the difference is up to ~1.2e-11 at note 127,
 * dominated by EXACT's own ~1e-12-cycle phase rounding (see [IconRenderer]); far inside the 1e-6 budget.
 */
internal class IconSynthesizer(
    private val timeline: EnvelopeTimeline,
    private val clock: SampleClock,
    private val carrierOffset: Long,
    val mode: RenderMode,
) : SampleSource {
    override val totalSamples: Long = timeline.sampleCount
    override var position: Long = 0
        private set

    // The envelope run the next sample lies in, found lazily as the stream advances.
    private val sweep = EnvelopeSweep(timeline)

    // EXACT carrier state: carrier index (position + carrierOffset) = second · fs + sampleInSecond.
    private val sampleRate = clock.sampleRate
    private var second = Math.floorDiv(carrierOffset, sampleRate.toLong())
    private var sampleInSecond = Math.floorMod(carrierOffset, sampleRate.toLong()).toInt()
    private var secondCycles = clock.cyclesAtSecond(second)

    // FAST carrier state: the lanes hold the phases of the next four samples.
    private val phasor = InterleavedPhasor(clock)

    override fun fill(destination: DoubleArray, offset: Int, length: Int): Int = fillRuns(length) { at, wanted ->
        when (mode) {
            RenderMode.EXACT -> fillExact(destination, offset + at, wanted)
            RenderMode.FAST -> fastChunk(wanted) { count, m -> phasor.fill(destination, offset + at, count, sweep.risingValue, sweep.risingSlope, sweep.fallingValue, sweep.fallingSlope, m) }
        }
    }

    /** FAST has a float kernel; EXACT narrows its doubles. */
    override val hasFloatKernel: Boolean get() = mode == RenderMode.FAST

    /** FAST's float kernel: as [fill], the samples narrowed to float32 as written (the same doubles, narrowed). */
    override fun fillFloats(destination: FloatArray, offset: Int, length: Int): Int {
        check(mode == RenderMode.FAST) { "EXACT has no float kernel" }
        return fillRuns(length) { at, wanted ->
            fastChunk(wanted) { count, m -> phasor.fill(destination, offset + at, count, sweep.risingValue, sweep.risingSlope, sweep.fallingValue, sweep.fallingSlope, m) }
        }
    }

    /** Up to [length] samples, run by run: [chunk] (samples written so far, samples wanted in this run) returns how many it wrote. */
    private inline fun fillRuns(length: Int, chunk: (Int, Int) -> Int): Int {
        val count = minOf(length.toLong(), totalSamples - position).toInt()
        var written = 0
        while (written < count) {
            if (position >= sweep.end) {
                sweep.advance()
                continue
            }
            val done = chunk(written, minOf((count - written).toLong(), sweep.end - position).toInt())
            written += done
            position += done
        }
        return written
    }

    private fun fillExact(destination: DoubleArray, offset: Int, wanted: Int): Int {
        if (sampleInSecond == sampleRate) {
            second++
            sampleInSecond = 0
            secondCycles = clock.cyclesAtSecond(second)
        }
        val chunk = minOf(wanted, sampleRate - sampleInSecond)
        val rv = sweep.risingValue
        val rsl = sweep.risingSlope
        val fv = sweep.fallingValue
        val fsl = sweep.fallingSlope
        var m = (position - sweep.start).toDouble()
        for (j in 0 until chunk) {
            val envelope = runValue(rv, rsl, fv, fsl, m)
            destination[offset + j] = envelope * sineOfCycles(clock.cyclesWithinSecond(secondCycles, sampleInSecond + j))
            m += 1.0
        }
        sampleInSecond += chunk
        return chunk
    }

    /** Anchors the phasor on the grid, then has [kernel] write (samples, run-relative index m) up to the next anchor. */
    private inline fun fastChunk(wanted: Int, kernel: (Int, Double) -> Unit): Int {
        val intoInterval = (position % FAST_ANCHOR_INTERVAL).toInt()
        if (intoInterval == 0) phasor.anchor(clock.cyclesAt(position + carrierOffset))
        val chunk = minOf(wanted, FAST_ANCHOR_INTERVAL - intoInterval)
        kernel(chunk, (position - sweep.start).toDouble())
        return chunk
    }

    companion object {
        /** FAST re-anchors its phasor at every multiple of this many samples. */
        const val FAST_ANCHOR_INTERVAL: Int = 1024
    }
}
