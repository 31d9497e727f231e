package org.hapticon.core.signal

/**
 * [signals] played back to back: each starts when the previous one ends. Use [Silence] for gaps.
 * Length: the sum of the lengths. A signal covers [start, start + length); the value is 0 outside
 * all of them.
 *
 * Note: in files that also use Kotlin's `kotlin.sequences.Sequence`, import this one explicitly.
 *
 * @throws IllegalArgumentException if any signal has an infinite length.
 */
public class Sequence(signals: List<Signal>) : Signal {
    /** Plays [signals] back to back; see the primary constructor. */
    public constructor(vararg signals: Signal) : this(signals.toList())

    /** The signals in playing order (a copy of the constructor argument). */
    public val signals: List<Signal> = signals.toList()

    init {
        require(this.signals.all { it.length.isFinite() }) { "only finite signals can be sequenced" }
    }

    private val starts: DoubleArray = DoubleArray(this.signals.size).also { starts ->
        var start = 0.0
        for (i in this.signals.indices) {
            starts[i] = start
            start += this.signals[i].length
        }
    }

    override val length: Double = this.signals.sumOf { it.length }

    /** The value of the signal playing at [t], in its own time; throws [IllegalArgumentException] for a non-finite [t]. */
    override fun sample(t: Double): Double {
        requireFiniteTime(t)
        // The last signal starting at or before t plays there (earlier ones with the same start have length 0).
        for (i in signals.indices.reversed()) {
            if (starts[i] <= t) {
                val local = t - starts[i]
                return if (local < signals[i].length) signals[i].sample(local) else 0.0
            }
        }
        return 0.0
    }
}
