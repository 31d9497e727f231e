package org.hapticon.core.signal

import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.sin

/**
 * A sine oscillator: sin(2π · frequency · t), 0 at t = 0, endless.
 *
 * @property frequency cycles per second.
 * @throws IllegalArgumentException if [frequency] is not finite.
 */
public class Sine(public val frequency: Double) : Signal {
    init {
        require(frequency.isFinite()) { "frequency must be finite, was $frequency" }
    }

    override val length: Double get() = Double.POSITIVE_INFINITY

    /** sin(2π · phase), phase reduced to [0, 1) cycles first; throws [IllegalArgumentException] for a non-finite [t]. */
    override fun sample(t: Double): Double = sineOfCycles(Phase.cyclesAt(frequency, t))
}

/**
 * A triangle oscillator of amplitude 1: 0 at t = 0, rising to 1 at a quarter cycle, −1 at three quarters.
 *
 * @property frequency cycles per second.
 * @throws IllegalArgumentException if [frequency] is not finite.
 */
public class Triangle(public val frequency: Double) : Signal {
    init {
        require(frequency.isFinite()) { "frequency must be finite, was $frequency" }
    }

    override val length: Double get() = Double.POSITIVE_INFINITY

    /** The triangle value at [t]; throws [IllegalArgumentException] for a non-finite [t]. */
    override fun sample(t: Double): Double = triangleOfCycles(Phase.cyclesAt(frequency, t))
}

/**
 * A square oscillator: +1 for the first half of each cycle (starting at t = 0), −1 for the second.
 *
 * @property frequency cycles per second.
 * @throws IllegalArgumentException if [frequency] is not finite.
 */
public class Square(public val frequency: Double) : Signal {
    init {
        require(frequency.isFinite()) { "frequency must be finite, was $frequency" }
    }

    override val length: Double get() = Double.POSITIVE_INFINITY

    /** +1 or −1 at [t]; throws [IllegalArgumentException] for a non-finite [t]. */
    override fun sample(t: Double): Double = if (Phase.cyclesAt(frequency, t) < 0.5) 1.0 else -1.0
}

/** sin(2π · cycles) for cycles in [0, 1); the small argument keeps Math.sin on its fast path. */
internal fun sineOfCycles(cycles: Double): Double = sin(TWO_PI * cycles)

/** cos(2π · cycles) for cycles in [0, 1). */
internal fun cosineOfCycles(cycles: Double): Double = cos(TWO_PI * cycles)

private fun triangleOfCycles(cycles: Double): Double = when {
    cycles < 0.25 -> 4.0 * cycles
    cycles < 0.75 -> 2.0 - 4.0 * cycles
    else -> 4.0 * cycles - 4.0
}

private const val TWO_PI: Double = 2.0 * PI
