package org.hapticon.core.signal

import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.floor
import kotlin.math.sin

// Phase arithmetic in cycles, shared by the icon carrier ([SampleClock], the FAST phasor) and the pattern signal.

/** sin(2π · cycles) for cycles in [0, 1); the small argument keeps Math.sin on its fast path. */
internal fun sineOfCycles(cycles: Double): Double = sin(TWO_PI * cycles)

/** cos(2π · cycles) for cycles in [0, 1). */
internal fun cosineOfCycles(cycles: Double): Double = cos(TWO_PI * cycles)

/** x − floor(x), forced into [0, 1) (a tiny negative x would otherwise round up to exactly 1.0). */
internal fun fractionOf(x: Double): Double {
    val fraction = x - floor(x)
    return if (fraction < 1.0) fraction else 0.0
}

private const val TWO_PI: Double = 2.0 * PI
