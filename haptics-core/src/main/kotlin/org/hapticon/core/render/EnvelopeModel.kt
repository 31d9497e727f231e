package org.hapticon.core.render

/** How an icon's attack/sustain/level/release become an amplitude envelope. */
public enum class EnvelopeModel {
    /** 0→level over attack, hold level for sustain, level→0 over release (the study's description). */
    PAPER,

    /**
     * Processing Sound 2.3's `Env.play(SinOsc, A, S, L, R)`, which rendered the study's stimuli:
     * 0→1 over attack, 1→level over sustain, level→0 over release, evaluated per sample.
     */
    PROCESSING,
}

/** How the carrier sine is computed. */
public enum class RenderMode {
    /** A sine of the exact phase at every sample. */
    EXACT,

    /** A cheaper oscillator whose error against [EXACT] stays within 1e-6. */
    FAST,
}
