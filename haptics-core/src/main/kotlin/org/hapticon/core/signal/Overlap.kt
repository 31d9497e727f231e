package org.hapticon.core.signal

/** How a [Repeater] combines repetitions that overlap in time. */
public enum class Overlap {
    /** The largest value of the overlapping repetitions: envelope semantics, never exceeds one repetition's peak. */
    MAX,

    /** The sum of the overlapping repetitions: audio-mixing semantics. */
    SUM,
}
