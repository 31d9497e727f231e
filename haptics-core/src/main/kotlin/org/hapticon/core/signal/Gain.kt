package org.hapticon.core.signal

/**
 * [signal] scaled by the constant [gain]; same length. `signal * g` builds one, and scaling a
 * [Gain] again folds into a single [Gain] rather than nesting.
 *
 * @property signal the signal being scaled.
 * @property gain the constant factor.
 * @throws IllegalArgumentException if [gain] is not finite.
 */
public class Gain(public val signal: Signal, public val gain: Double) : Signal {
    init {
        require(gain.isFinite()) { "gain must be finite, was $gain" }
    }

    override val length: Double get() = signal.length

    /** gain · signal(t); throws [IllegalArgumentException] for a non-finite [t]. */
    override fun sample(t: Double): Double {
        requireFiniteTime(t)
        return gain * signal.sample(t)
    }
}
