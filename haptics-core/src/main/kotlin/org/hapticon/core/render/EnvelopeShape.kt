package org.hapticon.core.render

import org.hapticon.core.HapticIcon

/**
 * One repetition of an icon's envelope under a model, in continuous time: the one definition of its corners
 * and of how repetitions combine. Every output derives from it:
 *
 * - sampled: [envelopeSegments] cuts it into per-sample pieces (PAPER samples these lines exactly; PROCESSING
 *   plays the same three targets through JSyn's reader rules, [ProcessingEnvelope]) and [EnvelopeTimeline]
 *   combines the repetitions, for the PCM, the vibrator's steps and control points and the plots;
 * - continuous: [org.hapticon.core.pattern.toPattern] takes the corners and their values ([valueAfter],
 *   [valueBefore]) for the Android 16 path and the "how it will feel there" line.
 *
 * The curve is 0 at the onset, [peak] at the end of the attack, [level] at the end of the sustain and 0 at the end
 * of the release, straight between:
 * - PAPER, the study's text: the attack rises to the level, which the sustain holds ([peak] = [level]);
 *   overlapping repetitions take the maximum.
 * - PROCESSING, Processing Sound's `Env.play` (processing-sound `Env.java` lines 29–34: frames (attackTime,
 *   1), (sustainTime, sustainLevel), (releaseTime, 0)): the attack rises to 1 and the sustain decays from 1 to
 *   the level ([peak] = 1); overlapping repetitions are **added** ([sums]), as JSyn's `InputMixingBlockPart`
 *   sums every reader connected to the amplitude port.
 *
 * @property model the model this shape is of.
 * @property peak the value at the end of the attack.
 * @property sums true when overlapping repetitions add (PROCESSING), false when the larger wins (PAPER).
 */
internal class EnvelopeShape private constructor(
    val model: EnvelopeModel,
    val attack: Double,
    val sustain: Double,
    val release: Double,
    val level: Double,
    val peak: Double,
    val sums: Boolean,
) {
    /** attack + sustain + release, summed as [HapticIcon.envelopeDuration] is. */
    val duration: Double = attack + sustain + release

    /** The repetition starting at [start]'s corner times: onset, attack's end, sustain's end, release's end. */
    fun corners(start: Double): DoubleArray = doubleArrayOf(start, start + attack, start + attack + sustain, start + duration)

    /** The value at absolute time [t] of the repetition starting at [start], the limit from the right. */
    fun valueAfter(t: Double, start: Double): Double = when {
        t < start -> 0.0
        t < start + attack -> peak * (t - start) / attack
        t < start + attack + sustain -> peak + (level - peak) * (t - start - attack) / sustain
        t < start + duration -> level * (start + duration - t) / release
        else -> 0.0
    }

    /** As [valueAfter], the limit from the left: the two differ only at a zero-length attack, sustain or release. */
    fun valueBefore(t: Double, start: Double): Double = when {
        t <= start -> 0.0
        t < start + attack -> peak * (t - start) / attack
        t == start + attack -> peak
        t <= start + attack + sustain -> peak + (level - peak) * (t - start - attack) / sustain
        t <= start + duration -> level * (start + duration - t) / release
        else -> 0.0
    }

    companion object {
        /** [icon]'s envelope shape under [model]. */
        fun of(icon: HapticIcon, model: EnvelopeModel): EnvelopeShape = when (model) {
            EnvelopeModel.PAPER -> EnvelopeShape(model, icon.attack, icon.sustain, icon.release, icon.level, peak = icon.level, sums = false)
            EnvelopeModel.PROCESSING -> EnvelopeShape(model, icon.attack, icon.sustain, icon.release, icon.level, peak = 1.0, sums = true)
        }
    }
}
