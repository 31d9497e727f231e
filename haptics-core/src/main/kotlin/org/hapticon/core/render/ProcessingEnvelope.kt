package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import kotlin.math.ceil

/**
 * The envelope the originating study's participants felt: Processing Sound 2.0.1–2.3.1's
 * `Env.play(input, attackTime, sustainTime, sustainLevel, releaseTime)` played through JSyn, one
 * repetition, simulated sample by sample at the render rate. The rules, with their sources
 * (processing/processing-sound `src/processing/sound/Env.java` at 3ca348e; philburk/jsyn
 * `src/main/java/com/jsyn/...`); docs/envelope-models.md has the table:
 *
 * 1. **Frames.** `Env.java` lines 29–34 build a `SegmentedEnvelope` of three (duration, target)
 *    frames: (attackTime, input.amp), (sustainTime, sustainLevel · input.amp), (releaseTime, 0.0).
 *    `input.amp` is 1 for an oscillator whose amplitude was never set. All four parameters are Java
 *    `float`s widened to double (line 29), so every duration and the level go through `float` here
 *    (0.01 s becomes 0.009999999776482582 s).
 * 2. **Segment rate.** `data/SegmentedEnvelope.getRateScaler` returns 1 / max(duration, framePeriod)
 *    and `unitgen/VariableRateMonoReader.java` line 106 multiplies it by the frame period 1/fs: the
 *    phase of a segment advances by framePeriod / max(duration, framePeriod) per sample. A duration
 *    under one sample therefore lasts exactly one sample.
 * 3. **Output and carry.** `VariableRateMonoReader.generate` outputs source + (target − source) ·
 *    phase (line 78), then adds the increment (line 82). When the phase reaches 1 (lines 63–68) it
 *    sets source = target, subtracts 1 — keeping the overshoot **in phase units** — and loads the next
 *    frame, whose increment then applies: knock's half-sample attack overshoot at 44.1 kHz becomes a
 *    whole sample of its twice-as-long sustain. The phase is a running double sum, so the sample on
 *    which it reaches 1 is found here by the same summation; values within a segment use
 *    phase₀ + m · increment (equal to the running sum within ~1e-12).
 * 4. **Start.** A new reader starts starved (lines 70–75): its first sample outputs 0 while it loads
 *    the attack frame.
 * 5. **End.** After the last frame the reader holds 0. `Env.java` lines 50–53 schedule the reader's
 *    disconnection from the oscillator's amplitude port at a `TimeStamp` attackTime + sustainTime +
 *    releaseTime (a float sum) after `createTimeStamp()`; when the carry makes the reader run past
 *    that time, its tail is cut there (see 6 for the sample).
 * 6. **Block quantisation.** JSyn runs every queued or time-stamped command only at the start of a
 *    synthesis block of `Synthesizer.FRAMES_PER_BLOCK` = 8 frames: `SynthesisEngine.generateNextBuffer`
 *    calls `processScheduledCommands(createTimeStamp())` before each block, `createTimeStamp()` is
 *    frameCount · framePeriod with frameCount advanced 8 at a time, `ScheduledQueue.removeNextList`
 *    releases every command stamped at or before that time, and `UnitDataQueuePort.queue(env)` goes
 *    through `queueCommand` (stamped now). So a reader starts on a block start (sample 0 here) and is
 *    disconnected at the first block start whose time is ≥ its stamp: sample 8·j for the smallest j
 *    with 8·j·framePeriod ≥ A + S + R ([disconnectSample]). For the presets at 44.1 and 48 kHz this
 *    moves nothing audible (every reader has reached 0 by then, except hug at 48 kHz whose cut falls
 *    on 144 000 = 8 · 18 000 either way); it matters for sub-sample envelopes, whose release it no
 *    longer cuts. The reader's start relative to the *nominal* onset k · period is **not** quantised
 *    here: the study's sketch called `Env.play` from its own thread at times we do not know (a
 *    sketch's `draw()` runs every 16.7 ms by default, ≫ one 0.18 ms block, and we do not have the
 *    study's sketch), so which block a repetition began on is unknowable; [EnvelopeTimeline] keeps
 *    onset(k) = round(k · period · fs).
 *
 * Overlapping repetitions add: `Env.java` line 40 leaves `input.amplitude.disconnectAll()` commented
 * out, and `ports/InputMixingBlockPart.getValues` sums every connected output ([EnvelopeTimeline]).
 * Sound 2.4.0 (2024) disconnects the running envelope instead; Hapticon models the study's versions.
 *
 * Simulating costs one addition per sample of one repetition (≤ 5.8 M for the 30 s cap at 192 kHz).
 */
internal object ProcessingEnvelope {
    /** Processing Sound's default output rate (`Engine`'s 44100 Hz), at which the study's stimuli were played. */
    const val PROCESSING_SAMPLE_RATE: Int = 44_100

    /** [value] rounded to a Java `float` and widened back, as `Env.play`'s float parameters are. */
    fun viaFloat(value: Double): Double = value.toFloat().toDouble()

    /** JSyn's `Synthesizer.FRAMES_PER_BLOCK`: commands (start, disconnect) take effect only on block starts. */
    const val FRAMES_PER_BLOCK: Int = 8

    /**
     * The sample from which one repetition is disconnected: the first block start (a multiple of
     * [FRAMES_PER_BLOCK] after the reader's start) whose time n · framePeriod is at or after A + S + R
     * (a float sum, widened), compared in doubles as JSyn's `TimeStamp.compareTo` does.
     */
    fun disconnectSample(icon: HapticIcon, sampleRate: Int): Long = disconnectSample(EnvelopeShape.of(icon, EnvelopeModel.PROCESSING), sampleRate)

    private fun disconnectSample(shape: EnvelopeShape, sampleRate: Int): Long {
        val total = (shape.attack.toFloat() + shape.sustain.toFloat() + shape.release.toFloat()).toDouble()
        val framePeriod = 1.0 / sampleRate
        // Start one block below the exact boundary and step up: the double comparison decides ties.
        var n = maxOf(0L, (ceil(total * sampleRate).toLong() / FRAMES_PER_BLOCK - 1) * FRAMES_PER_BLOCK)
        while (n * framePeriod < total) n += FRAMES_PER_BLOCK
        return n
    }

    /** One repetition of [icon]'s PROCESSING envelope at [sampleRate] ([envelopeSegments]). */
    fun segments(icon: HapticIcon, sampleRate: Int): List<EnvelopeSegment> = segments(EnvelopeShape.of(icon, EnvelopeModel.PROCESSING), sampleRate)

    /** The reader playing [shape]'s three frames (durations and targets through `float`, rule 1). */
    fun segments(shape: EnvelopeShape, sampleRate: Int): List<EnvelopeSegment> {
        val framePeriod = 1.0 / sampleRate
        val durations = doubleArrayOf(viaFloat(shape.attack), viaFloat(shape.sustain), viaFloat(shape.release))
        val targets = doubleArrayOf(viaFloat(shape.peak), viaFloat(shape.level), 0.0)
        val end = disconnectSample(shape, sampleRate)
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
