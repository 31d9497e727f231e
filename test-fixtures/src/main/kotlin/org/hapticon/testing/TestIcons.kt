package org.hapticon.testing

import org.hapticon.core.HapticIcon

/**
 * Edge-case icons shared by the tests of several modules. Each is a valid [HapticIcon]; the comment on
 * each says which limit or corner it sits on, and TestIconsTest checks that it really does.
 */
public object TestIcons {
    /**
     * The longest icon the safety caps allow, [HapticIcon.LONGEST_ALLOWED] (defined there once, so the
     * benchmark and every test use the same icon): [HapticIcon.MAX_COUNT] repetitions lasting exactly
     * [HapticIcon.MAX_DURATION_SECONDS]. Its repetitions overlap, so it is also the busiest envelope.
     */
    public val LONGEST: HapticIcon = HapticIcon.LONGEST_ALLOWED

    /** The lowest carrier, MIDI note 0 (8.18 Hz): less than one cycle per 100 ms. */
    public val NOTE_0: HapticIcon = HapticIcon("note-0", 0.01, 0.1, 1.0, 0.01, 0.0)

    /** The highest carrier, MIDI note 127 (12 543.85 Hz): renderable at 44.1 kHz, above Nyquist at 22.05 kHz and below. */
    public val NOTE_127: HapticIcon = HapticIcon("note-127", 0.01, 0.1, 1.0, 0.01, 127.0)

    /** Attack, sustain and release all 0: zero samples at any rate. */
    public val ZERO_LENGTH: HapticIcon = HapticIcon("zero-length", 0.0, 0.0, 0.5, 0.0, 60.0)

    /** Attack 0: every repetition starts with a step straight to its level. */
    public val STEP_ONSET: HapticIcon = HapticIcon("step-onset", 0.0, 0.05, 0.8, 0.05, 60.0, 0.2, 3)

    /** Repetitions overlap: 0.3 s envelopes every 0.15 s, combined by maximum. */
    public val OVERLAPPING: HapticIcon = HapticIcon("overlapping", 0.1, 0.1, 0.6, 0.1, 60.0, 0.15, 4)

    /** All of the above, for tests that run every edge case through the same check. */
    public val EDGE_CASES: List<HapticIcon> = listOf(LONGEST, NOTE_0, NOTE_127, ZERO_LENGTH, STEP_ONSET, OVERLAPPING)
}
