package org.hapticon.core.signal

/**
 * Zero for [duration] seconds: a gap in a [Sequence].
 *
 * @property duration seconds of silence.
 * @throws IllegalArgumentException if [duration] is negative or not finite.
 */
public class Silence(public val duration: Double) : Signal {
    init {
        requireDurations(duration)
    }

    override val length: Double get() = duration

    /** Always 0; throws [IllegalArgumentException] for a non-finite [t]. */
    override fun sample(t: Double): Double {
        requireFiniteTime(t)
        return 0.0
    }
}
