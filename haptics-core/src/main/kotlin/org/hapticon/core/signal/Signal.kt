package org.hapticon.core.signal

/**
 * A signal of time: a small immutable value that can be sampled at any time t (seconds). An icon's envelope
 * ([org.hapticon.core.render.envelope]) and a pattern ([org.hapticon.core.pattern.signal]) are signals;
 * [org.hapticon.core.render.stream] samples any of them.
 *
 * Time convention: a signal starts at t = 0 and plays for [length] seconds, and is 0 before 0 and after its end
 * unless documented otherwise. A signal throws [IllegalArgumentException] when sampled at a NaN or infinite time,
 * because no meaningful value exists there and a silent NaN would otherwise reach an actuator.
 */
public interface Signal {
    /**
     * The value of this signal at time [t] seconds.
     *
     * @throws IllegalArgumentException if [t] is NaN or infinite.
     */
    public fun sample(t: Double): Double

    /** How long this signal plays, in seconds. */
    public val length: Double
}
