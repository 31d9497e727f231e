package org.hapticon.core.signal

import kotlin.math.floor

/**
 * Oscillator phase arithmetic that stays accurate over hours.
 *
 * Phase is counted in cycles and only its fractional part matters. The naive product
 * `frequency · t` grows to ~1e8 cycles after a few hours, where a double keeps only ~1e-8 cycles
 * of fraction; splitting time into whole seconds and a remainder (and frequency into whole Hz and a
 * fraction) keeps the error near 1e-12 cycles.
 */
public object Phase {
    /**
     * The fractional part of `frequency · t`, in [0, 1) cycles.
     *
     * @throws IllegalArgumentException if [frequency] or [t] is NaN or infinite.
     */
    public fun cyclesAt(frequency: Double, t: Double): Double {
        require(frequency.isFinite()) { "frequency must be finite, was $frequency" }
        requireFiniteTime(t)
        val wholeSeconds = floor(t)
        val secondFraction = t - wholeSeconds
        // Whole Hz times whole seconds is a whole number of cycles, so only the Hz fraction
        // contributes phase over the whole seconds.
        val hzFraction = frequency - floor(frequency)
        return fractionOf(hzFraction * wholeSeconds + frequency * secondFraction)
    }
}

/** x − floor(x), forced into [0, 1) (a tiny negative x would otherwise round up to exactly 1.0). */
internal fun fractionOf(x: Double): Double {
    val fraction = x - floor(x)
    return if (fraction < 1.0) fraction else 0.0
}
