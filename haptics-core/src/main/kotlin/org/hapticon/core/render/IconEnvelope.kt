package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.hapticon.core.signal.Signal

/**
 * This icon's amplitude envelope over all its repetitions as a [Signal] of time: the same definition
 * [IconRenderer] samples ([EnvelopeShape], as [EnvelopeTimeline] places it over [envelopeSegments]), evaluated in continuous time
 * at [sampleRate]'s sample grid (onsets on whole samples). [VibrationWaveform], [EnvelopeControlPoints]
 * and the plots read it, so a model change reaches every output at once.
 *
 * - [EnvelopeModel.PAPER]: 0 → level over attack, level for sustain, level → 0 over release, exact in
 *   time (zero-length segments are skipped: attack 0 starts at level); overlapping repetitions take
 *   the maximum. Independent of [sampleRate] except for onsets rounded to its samples.
 * - [EnvelopeModel.PROCESSING]: Processing Sound's reader ([ProcessingEnvelope]) at [sampleRate], its
 *   lines joined straight between samples; overlapping repetitions add. [sampleRate] defaults to
 *   Processing's own 44100 Hz, the rate at which the study's stimuli were played.
 *
 * The length is [HapticIcon.duration]; the value is 0 outside [0, round(duration · sampleRate) / sampleRate).
 */
public fun HapticIcon.envelope(
    model: EnvelopeModel = EnvelopeModel.DEFAULT,
    sampleRate: Int = ProcessingEnvelope.PROCESSING_SAMPLE_RATE,
): Signal {
    val timeline = EnvelopeTimeline(this, model, sampleRate, Math.round(duration * sampleRate))
    val length = duration
    return object : Signal {
        override val length: Double = length

        override fun sample(t: Double): Double {
            require(t.isFinite()) { "sample time must be finite, was $t" }
            return timeline.valueAtTime(t)
        }
    }
}
