package org.hapticon.core.signal

/** The [Product] of this signal and [other]; it ends when the shorter one ends. */
public operator fun Signal.times(other: Signal): Signal = Product(this, other)

/** The [Sum] of this signal and [other]; it ends when the longer one ends. */
public operator fun Signal.plus(other: Signal): Signal = Sum(this, other)

/**
 * This signal scaled by [gain]; a [Gain] is folded into one [Gain] instead of nesting.
 *
 * @throws IllegalArgumentException if the resulting gain is not finite.
 */
public operator fun Signal.times(gain: Double): Signal =
    if (this is Gain) Gain(signal, this.gain * gain) else Gain(this, gain)

/** [signal] scaled by this number; same as `signal * this`. Throws [IllegalArgumentException] if the gain is not finite. */
public operator fun Double.times(signal: Signal): Signal = signal * this
