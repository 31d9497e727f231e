package org.hapticon.core.render

/**
 * How an icon's attack/sustain/level/release become an amplitude envelope. Both models are defined
 * once, as an [EnvelopeShape]; every output (PCM, the vibrator's amplitude steps and control points,
 * plots, the icon as a pattern) derives from that definition.
 */
public enum class EnvelopeModel {
    /**
     * 0→level over attack, hold level for sustain, level→0 over release: the trapezoid the study's text
     * describes. Overlapping repetitions combine by maximum.
     */
    PAPER,

    /**
     * What the study's participants felt: Processing Sound 2.0.1–2.3.1's `Env.play(SinOsc, A, S, L, R)`
     * through JSyn, sample for sample — 0→1 over attack, 1→level over sustain, level→0 over release,
     * each segment's phase advancing by 1/(duration · fs) per sample with the overshoot carried into the
     * next segment, durations under one sample lasting one sample, and overlapping repetitions **added**
     * (JSyn's `InputMixingBlockPart` sums every reader connected to the amplitude port). See
     * [ProcessingEnvelope] and docs/envelope-models.md. The default.
     */
    PROCESSING,
    ;

    public companion object {
        /**
         * The model presets are played and rendered with unless the user picks another: [PROCESSING], what the
         * participants felt. It assumes Processing Sound 2.0.1–2.3.1: the paper names only "the Sound Library in
         * Processing 3" (000_f26496a15a0d284b.txt:66, :95); it cites work of 2018 (:175), so the study ran in 2018 or
         * later, when Processing 3's Sound library was the JSyn-based 2.x, whose `Env` is the same from 2.0.1 to 2.3.1
         * (docs/envelope-models.md). Another version would change only overlapping repetitions (stroke): 2.4.0
         * replaces a running envelope instead of adding to it.
         */
        public val DEFAULT: EnvelopeModel = PROCESSING
    }
}

/** How the carrier sine is computed. */
public enum class RenderMode {
    /** A sine of the exact phase at every sample. */
    EXACT,

    /** A cheaper oscillator whose error against [EXACT] stays within 1e-6. */
    FAST,
}
