package org.hapticon.core.signal

/**
 * A signal of time: a small immutable value that can be sampled at any time t (seconds).
 *
 * Signals compose: `a * b` is a [Product], `a + b` a [Sum], `a * 0.5` a [Gain] (see SignalOperators.kt);
 * [Repeater] and [Sequence] place signals in time.
 *
 * Time convention: a signal starts at t = 0 and plays for [length] seconds. Finite signals are 0
 * before 0 and after their end unless documented otherwise. Every signal in this package throws
 * [IllegalArgumentException] when sampled at a NaN or infinite time, because no meaningful value
 * exists there and a silent NaN would otherwise reach an actuator.
 */
public interface Signal {
    /**
     * The value of this signal at time [t] seconds.
     *
     * @throws IllegalArgumentException if [t] is NaN or infinite.
     */
    public fun sample(t: Double): Double

    /** How long this signal plays, in seconds; [Double.POSITIVE_INFINITY] for oscillators. */
    public val length: Double
}

/** Shared guard for [Signal.sample]: rejects NaN and infinite times. */
internal fun requireFiniteTime(t: Double) {
    require(t.isFinite()) { "sample time must be finite, was $t" }
}
