package org.hapticon.core.render

import org.hapticon.core.signal.SampleClock
import org.hapticon.core.signal.cosineOfCycles
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
 * FAST: a rotating phasor, re-anchored from the exact phase at every sample index that is a
 * multiple of [FAST_ANCHOR_INTERVAL]. Anchors sit on a fixed grid of indices, so the output does
 * not depend on how reads are split into blocks; the phasor's own rounding grows over at most one
 * interval (~1e-13). Against EXACT in double precision the difference is up to ~1.2e-11 at note 127,
 * dominated by EXACT's own ~1e-12-cycle phase rounding (see [IconRenderer]); far inside the 1e-6 budget.
 */
internal class IconSynthesizer(
    private val timeline: EnvelopeTimeline,
    private val clock: SampleClock,
    private val carrierOffset: Long,
    private val mode: RenderMode,
) {
    val totalSamples: Long = timeline.sampleCount
    var position: Long = 0
        private set

    // The envelope run the next sample lies in, found lazily as the stream advances.
    private val sweep = EnvelopeSweep(timeline)

    // EXACT carrier state: carrier index (position + carrierOffset) = second · fs + sampleInSecond.
    private val sampleRate = clock.sampleRate
    private var second = Math.floorDiv(carrierOffset, sampleRate.toLong())
    private var sampleInSecond = Math.floorMod(carrierOffset, sampleRate.toLong()).toInt()
    private var secondCycles = clock.cyclesAtSecond(second)

    // FAST carrier state: (phasorCos, phasorSin) = cis(2π · phase) of the next sample.
    private val rotationCos = cosineOfCycles(clock.frequency / sampleRate)
    private val rotationSin = sineOfCycles(clock.frequency / sampleRate)
    private var phasorCos = 1.0
    private var phasorSin = 0.0

    /** Writes up to [length] next samples into [destination] from [offset]; returns how many (0 at the end). */
    fun fill(destination: DoubleArray, offset: Int, length: Int): Int {
        val count = minOf(length.toLong(), totalSamples - position).toInt()
        var written = 0
        while (written < count) {
            if (position >= sweep.end) {
                sweep.advance()
                continue
            }
            val wanted = minOf((count - written).toLong(), sweep.end - position).toInt()
            val done = when (mode) {
                RenderMode.EXACT -> fillExact(destination, offset + written, wanted)
                RenderMode.FAST -> fillFast(destination, offset + written, wanted)
            }
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

    private fun fillFast(destination: DoubleArray, offset: Int, wanted: Int): Int {
        val intoInterval = (position % FAST_ANCHOR_INTERVAL).toInt()
        if (intoInterval == 0) {
            val cycles = clock.cyclesAt(position + carrierOffset)
            phasorCos = cosineOfCycles(cycles)
            phasorSin = sineOfCycles(cycles)
        }
        val chunk = minOf(wanted, FAST_ANCHOR_INTERVAL - intoInterval)
        val rc = rotationCos
        val rs = rotationSin
        var c = phasorCos
        var s = phasorSin
        val rv = sweep.risingValue
        val rsl = sweep.risingSlope
        val fv = sweep.fallingValue
        val fsl = sweep.fallingSlope
        var m = (position - sweep.start).toDouble()
        for (j in 0 until chunk) {
            destination[offset + j] = runValue(rv, rsl, fv, fsl, m) * s
            val nextCos = c * rc - s * rs
            s = s * rc + c * rs
            c = nextCos
            m += 1.0
        }
        phasorCos = c
        phasorSin = s
        return chunk
    }

    companion object {
        /** FAST re-anchors its phasor at every multiple of this many samples. */
        const val FAST_ANCHOR_INTERVAL: Int = 1024
    }
}
