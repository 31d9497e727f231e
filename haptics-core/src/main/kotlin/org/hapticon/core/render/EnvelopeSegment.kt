package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import kotlin.math.ceil

/**
 * One linear piece of a single envelope repetition, in that repetition's own sample index n
 * (n = 0 at its onset): covers [firstSample, endSample) with value startValue + slope · (n − origin).
 * [rising] marks the attack: the only piece whose value grows with n (this is what lets overlapping
 * repetitions be combined by max from just two candidates, see [EnvelopeTimeline]).
 */
internal class EnvelopeSegment(
    val firstSample: Long,
    val endSample: Long,
    val startValue: Double,
    val slope: Double,
    val origin: Double,
    val rising: Boolean,
) {
    fun valueAt(n: Long): Double = startValue + slope * (n - origin)
}

/**
 * The non-empty pieces of one repetition of [icon]'s envelope at [sampleRate].
 *
 * PAPER samples the continuous ideal: sample n is in a piece when n / fs lies in its time span,
 * so boundaries are ceil(boundary time · fs) and each line is anchored at the exact (fractional)
 * boundary position.
 *
 * PROCESSING works in whole samples like Processing's per-sample envelope: boundaries are the
 * cumulative boundary times rounded to the nearest sample (half up),
 * round(A·fs), round((A+S)·fs), round((A+S+R)·fs), so rounding never accumulates over segments
 * and one envelope spans round((A+S+R)·fs) samples. Sample n of a segment (n counted from the
 * segment's first sample) is start + (target − start) · n / (duration · fs) with the unrounded
 * duration, as in Processing.
 */
internal fun envelopeSegments(icon: HapticIcon, model: EnvelopeModel, sampleRate: Int): List<EnvelopeSegment> {
    val fs = sampleRate.toDouble()
    val a = icon.attack
    val s = icon.sustain
    val r = icon.release
    val level = icon.level
    val segments = when (model) {
        EnvelopeModel.PAPER -> {
            val attackEnd = a * fs
            val sustainEnd = (a + s) * fs
            val releaseEnd = (a + s + r) * fs
            val b1 = ceil(attackEnd).toLong()
            val b2 = ceil(sustainEnd).toLong()
            val b3 = ceil(releaseEnd).toLong()
            listOf(
                EnvelopeSegment(0, b1, 0.0, level / attackEnd, 0.0, rising = true),
                EnvelopeSegment(b1, b2, level, 0.0, 0.0, rising = false),
                EnvelopeSegment(b2, b3, level, -level / (r * fs), sustainEnd, rising = false),
            )
        }
        EnvelopeModel.PROCESSING -> {
            val b1 = Math.round(a * fs)
            val b2 = Math.round((a + s) * fs)
            val b3 = Math.round((a + s + r) * fs)
            listOf(
                EnvelopeSegment(0, b1, 0.0, 1.0 / (a * fs), 0.0, rising = true),
                EnvelopeSegment(b1, b2, 1.0, (level - 1.0) / (s * fs), b1.toDouble(), rising = false),
                EnvelopeSegment(b2, b3, level, -level / (r * fs), b2.toDouble(), rising = false),
            )
        }
    }
    // An empty piece may carry a division by zero; it is never evaluated, so drop it here.
    return segments.filter { it.endSample > it.firstSample }
}
