package org.hapticon.core.signal

/**
 * [left] × [right], sample by sample. It ends when its shorter factor ends, so
 * `Sine(f) * Asr(a, s, r)` lasts as long as its envelope.
 *
 * @property left the first factor.
 * @property right the second factor.
 */
public class Product(public val left: Signal, public val right: Signal) : Signal {
    override val length: Double = minOf(left.length, right.length)

    /** left(t) · right(t); throws [IllegalArgumentException] for a non-finite [t]. */
    override fun sample(t: Double): Double {
        requireFiniteTime(t)
        return left.sample(t) * right.sample(t)
    }
}
