package org.hapticon.core.signal

/**
 * [left] + [right], sample by sample. It lasts as long as its longer term.
 *
 * @property left the first term.
 * @property right the second term.
 */
public class Sum(public val left: Signal, public val right: Signal) : Signal {
    override val length: Double = maxOf(left.length, right.length)

    /** left(t) + right(t); throws [IllegalArgumentException] for a non-finite [t]. */
    override fun sample(t: Double): Double {
        requireFiniteTime(t)
        return left.sample(t) + right.sample(t)
    }
}
