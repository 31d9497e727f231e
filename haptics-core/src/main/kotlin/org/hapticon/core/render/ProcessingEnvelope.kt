package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import kotlin.math.ceil

/**
 * The envelope the originating study's participants felt: Processing Sound 2.0.1–2.3.1's
 * `Env.play(input, attackTime, sustainTime, sustainLevel, releaseTime)` played through JSyn, one
 * repetition, simulated sample by sample at the render rate. The rules, with their sources (files
 * of processing/processing-sound and philburk/jsyn):
 *
 * 1. **Frames.** `Env.java` (lines 29–34 in 2.0.1–2.3.1) builds a `SegmentedEnvelope` of three
 *    (duration, target) frames: (attackTime, input.amp), (sustainTime, sustainLevel · input.amp),
 *    (releaseTime, 0.0). `input.amp` is 1 for an oscillator whose amplitude was never set; all four
 *    parameters are Java `float`s, widened to double, so every duration and the level here go
 *    through `float` first (0.01 s becomes 0.009999999776482582 s).
 * 2. **Segment rate.** `SegmentedEnvelope.getRateScaler` returns 1 / max(duration, framePeriod) and
 *    `VariableRateMonoReader.advanceToNextFrame` multiplies it by the frame period 1/fs: the phase
 *    of a segment advances by framePeriod / max(duration, framePeriod) per sample. A duration under
 *    one sample therefore lasts exactly one sample.
 * 3. **Output and carry.** `VariableRateMonoReader.generate` outputs source + (target − source) ·
 *    phase, then adds the increment. When the phase reaches 1 it sets source = target, subtracts 1
 *    (keeping the overshoot **in phase units**) and loads the next frame, whose increment then
 *    applies: an overshoot of 0.5 attack samples becomes 0.5 · (sustain length) sustain samples.
 *    The phase is a running double sum, so the sample on which it reaches 1 is found here by the
 *    same summation; values within a segment use phase₀ + m · increment (equal to the running sum
 *    within ~1e-15 · m).
 * 4. **Start.** A new reader starts starved: its first sample outputs 0 (source = target = 0,
 *    phase 0) while it loads the attack frame.
 * 5. **End.** After the last frame the reader holds source = 0. `Env.play` also disconnects the
 *    reader from the oscillator's amplitude port at attackTime + sustainTime + releaseTime (a float
 *    sum) after its start, so the repetition contributes nothing from sample
 *    ceil(that time · fs) on; when the phase carry makes the reader run past that sample, the tail is
 *    cut there.
 *
 * Overlapping repetitions add ([EnvelopeModel.PROCESSING]); see docs/envelope-models.md.
 * Simulating costs one addition per sample of one repetition (≤ 5.8 M for the 30 s cap at 192 kHz).
 */
internal object ProcessingEnvelope {
    /** Processing Sound's default output rate (`Engine`'s 44100 Hz), at which the study's stimuli were played. */
    const val PROCESSING_SAMPLE_RATE: Int = 44_100

    /** [value] rounded to a Java `float` and widened back, as `Env.play`'s float parameters are. */
    fun viaFloat(value: Double): Double = value.toFloat().toDouble()

    /** The sample from which one repetition is disconnected: ceil((A + S + R as a float sum) · fs). */
    fun disconnectSample(icon: HapticIcon, sampleRate: Int): Long {
        val total = icon.attack.toFloat() + icon.sustain.toFloat() + icon.release.toFloat()
        return ceil(total.toDouble() * sampleRate).toLong()
    }

    fun segments(icon: HapticIcon, sampleRate: Int): List<EnvelopeSegment> {
        val framePeriod = 1.0 / sampleRate
        val durations = doubleArrayOf(viaFloat(icon.attack), viaFloat(icon.sustain), viaFloat(icon.release))
        val targets = doubleArrayOf(1.0, viaFloat(icon.level), 0.0)
        val end = disconnectSample(icon, sampleRate)
        val segments = ArrayList<EnvelopeSegment>(3)
        var first = 0L
        var source = 0.0
        var phase = 0.0
        for (frame in 0 until 3) {
            if (first >= end) break
            val target = targets[frame]
            val increment = framePeriod * (1.0 / maxOf(durations[frame], framePeriod))
            val startPhase = phase
            // The running sum, exactly as the reader accumulates it: the segment ends at the first sample
            // on which the phase is ≥ 1, and no later than the disconnection.
            var n = first
            do {
                phase += increment
                n++
            } while (phase < 1.0 && n < end)
            val span = target - source
            segments.add(EnvelopeSegment(first, n, source + span * startPhase, span * increment, first.toDouble(), rising = frame == 0))
            first = n
            source = target
            phase -= 1.0
        }
        return segments
    }
}
