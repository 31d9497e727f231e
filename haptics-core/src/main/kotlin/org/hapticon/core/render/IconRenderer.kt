package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.hapticon.core.signal.SampleClock
import org.hapticon.core.signal.sineOfCycles

/**
 * Renders [icon] as envelope × sine carrier at [sampleRate] Hz: sample i is at t = i / sampleRate,
 * and there are [sampleCount] = round(duration · sampleRate) samples (half up; 0 for a
 * zero-duration icon).
 *
 * Envelope ([model], one definition for every output: [EnvelopeTimeline]): repetition k starts at
 * sample round(k · period · sampleRate) — exactly k · period whenever that is a whole number of
 * samples (every preset at 8, 44.1, 48, 96 and 192 kHz), otherwise on the nearest sample, so every
 * repetition has the same samples and a step onset (attack 0) can never be lost to rounding.
 * PAPER samples each repetition's continuous trapezoid at n / fs after its onset, overlapping
 * repetitions taking the maximum. PROCESSING is Processing Sound 2.0.1–2.3.1 + JSyn sample for
 * sample ([ProcessingEnvelope]: per-sample phase increments with the overshoot carried into the next
 * segment, durations under one sample lasting one sample), overlapping repetitions added.
 *
 * Carrier: PAPER is one continuous sine with phase 0 at sample 0 (sample 0 is 0). PROCESSING
 * reproduces Processing's SinOsc, which advances its phase by f/fs cycles before each sample, so
 * sample i has phase (i + 1) · f / fs. Phase is computed from the sample index, never summed, so
 * it stays within ~1e-12 cycles of exact over any supported length.
 *
 * [mode] chooses how [stream] computes the carrier: [RenderMode.EXACT] matches [sampleAt] exactly
 * (bit for bit when read as doubles, see [DoubleSampleStream]); [RenderMode.FAST] stays within 1e-6
 * of it. Measured in double precision FAST is within about 2e-13 of EXACT at mid notes and 1.2e-11
 * at note 127 (tests hold it to 1e-9). At high notes that difference is mostly EXACT's own phase
 * rounding (~1e-12 cycles, about 1e-11 from the true sine at note 127), not FAST's drift.
 *
 * Construction and [stream] do work independent of the icon's length and repetition count: the
 * envelope is computed run by run as a stream reaches each run, so the first block is ready
 * quickly even for the longest icon the safety caps allow ([HapticIcon.LONGEST_ALLOWED]).
 *
 * @property icon the icon rendered.
 * @property sampleRate samples per second, 8000..192000.
 * @property model how the envelope is shaped.
 * @property mode how [stream] computes the carrier.
 * @throws org.hapticon.core.IconValidationException if the icon cannot be rendered at
 *   [sampleRate] (rate outside 8..192 kHz, or carrier at or above Nyquist).
 */
public class IconRenderer(
    public val icon: HapticIcon,
    public val sampleRate: Int,
    public val model: EnvelopeModel = EnvelopeModel.DEFAULT,
    public val mode: RenderMode = RenderMode.EXACT,
) {
    init {
        icon.requireRenderableAt(sampleRate)
    }

    /** Number of samples in a render: round(duration · sampleRate), half up. */
    public val sampleCount: Long = Math.round(icon.duration * sampleRate)

    private val timeline = EnvelopeTimeline(icon, model, sampleRate, sampleCount)
    private val clock = SampleClock(icon.frequency, sampleRate)
    private val carrierOffset = if (model == EnvelopeModel.PROCESSING) 1L else 0L

    /**
     * A new stream over the whole render from sample 0, computing the carrier per [mode]. Each call
     * starts afresh. Read it as floats ([SampleStream.read]) or, for the samples before narrowing, as
     * doubles ([DoubleSampleStream.read]).
     */
    public fun stream(): DoubleSampleStream = SampleSourceStream(newSynthesizer(mode), sampleRate)

    /**
     * The exact sample at [index] (envelope × carrier, in double precision), whatever [mode] is:
     * the reference that [RenderMode.FAST] is measured against. Equal bit for bit to sample [index]
     * of an [RenderMode.EXACT] stream read as doubles. Finds the envelope by binary search over the
     * onsets; does not allocate.
     *
     * @throws IndexOutOfBoundsException unless 0 ≤ index < [sampleCount].
     */
    public fun sampleAt(index: Long): Double {
        checkIndex(index)
        return timeline.valueAt(index) * sineOfCycles(clock.cyclesAt(index + carrierOffset))
    }

    /**
     * The envelope (amplitude, 0..1) at sample [index].
     *
     * @throws IndexOutOfBoundsException unless 0 ≤ index < [sampleCount].
     */
    public fun envelopeAt(index: Long): Double {
        checkIndex(index)
        return timeline.valueAt(index)
    }

    /** A fresh engine over this render; [PcmRenderer] reads doubles from it directly. */
    internal fun newSynthesizer(carrierMode: RenderMode): IconSynthesizer =
        IconSynthesizer(timeline, clock, carrierOffset, carrierMode)

    private fun checkIndex(index: Long) {
        if (index < 0 || index >= sampleCount) {
            throw IndexOutOfBoundsException("sample $index is outside 0 until $sampleCount")
        }
    }
}
