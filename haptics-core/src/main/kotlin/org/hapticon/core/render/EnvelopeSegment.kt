package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import kotlin.math.ceil

/**
 * One linear piece of a single envelope repetition, in that repetition's own sample position x
 * (x = 0 at its onset): value startValue + slope · (x − origin).
 *
 * At sample resolution it covers the whole samples [firstSample, endSample); in continuous time it
 * covers the positions [from, to) (fractional for PAPER, whose boundaries are exact times; equal to
 * the sample bounds for PROCESSING, whose boundaries are whole samples). [rising] marks the attack:
 * the only piece whose value grows with x (this is what lets overlapping PAPER repetitions be
 * combined by max from just two candidates, see [EnvelopeTimeline]).
 */
internal class EnvelopeSegment(
    val firstSample: Long,
    val endSample: Long,
    val startValue: Double,
    val slope: Double,
    val origin: Double,
    val rising: Boolean,
    val from: Double = firstSample.toDouble(),
    val to: Double = endSample.toDouble(),
) {
    fun valueAt(n: Long): Double = startValue + slope * (n - origin)

    fun valueAt(x: Double): Double = startValue + slope * (x - origin)
}

/**
 * The pieces of one repetition of [icon]'s envelope at [sampleRate], in order: its [EnvelopeShape] under [model]
 * at sample resolution. Includes pieces that hold no whole sample (callers filter for what they evaluate:
 * [EnvelopeTimeline] keeps pieces with samples, continuous evaluation keeps pieces with a positive span).
 *
 * PAPER samples the shape's lines exactly: sample n is in a piece when n / fs lies in its time span,
 * so boundaries are ceil(boundary time · fs) and each line is anchored at the exact (fractional)
 * boundary position.
 *
 * PROCESSING plays the shape's targets the way the study's library did ([ProcessingEnvelope]): JSyn's
 * `VariableRateMonoReader` playing Processing Sound's three-frame `SegmentedEnvelope`, simulated sample by sample.
 */
internal fun envelopeSegments(icon: HapticIcon, model: EnvelopeModel, sampleRate: Int): List<EnvelopeSegment> {
    val shape = EnvelopeShape.of(icon, model)
    return when (model) {
        EnvelopeModel.PAPER -> paperSegments(shape, sampleRate)
        EnvelopeModel.PROCESSING -> ProcessingEnvelope.segments(shape, sampleRate)
    }
}

private fun paperSegments(shape: EnvelopeShape, sampleRate: Int): List<EnvelopeSegment> {
    val fs = sampleRate.toDouble()
    val level = shape.level
    val attackEnd = shape.attack * fs
    val sustainEnd = (shape.attack + shape.sustain) * fs
    val releaseEnd = (shape.attack + shape.sustain + shape.release) * fs
    val b1 = ceil(attackEnd).toLong()
    val b2 = ceil(sustainEnd).toLong()
    val b3 = ceil(releaseEnd).toLong()
    return listOf(
        EnvelopeSegment(0, b1, 0.0, shape.peak / attackEnd, 0.0, rising = true, from = 0.0, to = attackEnd),
        EnvelopeSegment(b1, b2, shape.peak, 0.0, 0.0, rising = false, from = attackEnd, to = sustainEnd),
        EnvelopeSegment(b2, b3, level, -level / (shape.release * fs), sustainEnd, rising = false, from = sustainEnd, to = releaseEnd),
    )
}
