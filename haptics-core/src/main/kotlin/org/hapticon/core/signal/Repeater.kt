package org.hapticon.core.signal

import kotlin.math.floor

/**
 * [signal] played [count] times, repetition k starting at k · [period] seconds (onset to onset).
 * Repetition k covers [k · period, k · period + signal.length); where repetitions overlap they
 * are combined by [overlap]; where none plays the value is 0.
 * Length: (count − 1) · period + signal.length.
 *
 * Windows are tested in floating-point time, so a sample time landing exactly on a window edge
 * (e.g. 0.013 − 0.010 < 0.003 in doubles) may fall on either side; [org.hapticon.core.render.IconRenderer]
 * works in integer sample indices for that reason.
 *
 * @property signal the repeated signal (finite length).
 * @property count how many times it plays.
 * @property period seconds from one onset to the next.
 * @property overlap how overlapping repetitions combine.
 * @throws IllegalArgumentException if [count] < 1, [period] is negative or not finite,
 *   [period] is 0 while [count] > 1, or [signal] has an infinite length.
 */
public class Repeater(
    public val signal: Signal,
    public val count: Int,
    public val period: Double,
    public val overlap: Overlap,
) : Signal {
    init {
        require(count >= 1) { "count must be >= 1, was $count" }
        require(period.isFinite() && period >= 0.0) { "period must be finite and >= 0, was $period" }
        require(count == 1 || period > 0.0) { "period must be > 0 when count > 1, was $period" }
        require(signal.length.isFinite()) { "only a finite signal can be repeated" }
    }

    override val length: Double = (count - 1) * period + signal.length

    /** The repetitions playing at [t], combined by [overlap]; throws [IllegalArgumentException] for a non-finite [t]. */
    override fun sample(t: Double): Double {
        requireFiniteTime(t)
        if (count == 1) return if (t >= 0.0 && t < signal.length) signal.sample(t) else 0.0
        // A candidate range one wider on each side than floor() suggests; the exact window test
        // below decides, so rounding in the division cannot drop a repetition.
        val first = maxOf(0.0, floor((t - signal.length) / period) - 1.0)
        val last = minOf(count - 1.0, floor(t / period) + 1.0)
        if (first > last) return 0.0
        var playing = false
        var combined = 0.0
        for (k in first.toInt()..last.toInt()) {
            val local = t - k * period
            if (local < 0.0 || local >= signal.length) continue
            val value = signal.sample(local)
            combined = when {
                !playing -> value
                overlap == Overlap.MAX -> maxOf(combined, value)
                else -> combined + value
            }
            playing = true
        }
        return combined
    }
}
