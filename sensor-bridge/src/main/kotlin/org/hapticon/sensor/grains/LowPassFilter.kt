package org.hapticon.sensor.grains

import kotlin.math.PI
import kotlin.math.exp

/**
 * A first-order IIR low-pass: y[n] = y[n−1] + a·(x[n] − y[n−1]) with a = 1 − e^(−2π·fc/fs), the
 * impulse-invariant discretisation of an RC filter with cutoff fc = [cutoffHz] at fs = [sampleRateHz].
 * The first sample initialises y to itself, so a recording that starts under load has no start-up ramp.
 * Allocation-free; not thread-safe.
 */
public class LowPassFilter(
    /** Cutoff frequency fc in Hz, in (0, fs/2). */
    public val cutoffHz: Double,
    /** Sample rate fs in Hz, in (0, [MAX_SAMPLE_RATE_HZ]]. */
    public val sampleRateHz: Double,
) {
    init {
        require(sampleRateHz > 0.0 && sampleRateHz <= MAX_SAMPLE_RATE_HZ) { "sampleRateHz must be in (0, $MAX_SAMPLE_RATE_HZ], was $sampleRateHz" }
        require(cutoffHz > 0.0 && cutoffHz < sampleRateHz / 2) { "cutoffHz must be in (0, ${sampleRateHz / 2}) for $sampleRateHz Hz, was $cutoffHz" }
    }

    /** The smoothing coefficient a = 1 − e^(−2π·fc/fs). */
    public val coefficient: Double = 1.0 - exp(-2.0 * PI * cutoffHz / sampleRateHz)

    private var state = 0.0
    private var primed = false

    /** The last output, or 0 before the first sample. */
    public val value: Double get() = state

    /** Filters [x] and returns y[n]. [x] must be finite (callers drop NaN/∞ first; one would poison the state). */
    public fun filter(x: Double): Double {
        state = if (primed) state + coefficient * (x - state) else x
        primed = true
        return state
    }

    /** Forgets the state: the next sample initialises it again. */
    public fun reset() {
        state = 0.0
        primed = false
    }

    public companion object {
        /** Highest sample rate accepted. */
        public const val MAX_SAMPLE_RATE_HZ: Double = 1.0e6
    }
}
