package org.hapticon.core.signal

import kotlin.math.floor

/**
 * Phase of a [frequency] Hz oscillator at integer sample indices of a [sampleRate] Hz stream,
 * with sample i at time i / sampleRate and phase 0 at sample 0.
 *
 * The index is split into whole seconds and a sample-within-second so the phase error stays
 * around 1e-12 cycles at any length (a running double sum would drift).
 *
 * @property frequency oscillator frequency in Hz.
 * @property sampleRate samples per second.
 * @throws IllegalArgumentException if [frequency] is not finite or [sampleRate] is not positive.
 */
public class SampleClock(public val frequency: Double, public val sampleRate: Int) {
    init {
        require(frequency.isFinite()) { "frequency must be finite, was $frequency" }
        require(sampleRate > 0) { "sampleRate must be positive, was $sampleRate" }
    }

    private val cyclesPerSample = frequency / sampleRate
    private val hzFraction = frequency - floor(frequency)

    /** The fractional phase in [0, 1) cycles at sample [index] (negative indices count back from 0). */
    public fun cyclesAt(index: Long): Double {
        val second = Math.floorDiv(index, sampleRate.toLong())
        val sampleInSecond = Math.floorMod(index, sampleRate.toLong()).toInt()
        return cyclesWithinSecond(cyclesAtSecond(second), sampleInSecond)
    }

    /** Phase at the first sample of whole second [second]; streaming code calls this once a second. */
    internal fun cyclesAtSecond(second: Long): Double = fractionOf(hzFraction * second)

    /** Phase at [sampleInSecond] samples after a second that starts at [secondCycles]. */
    internal fun cyclesWithinSecond(secondCycles: Double, sampleInSecond: Int): Double =
        fractionOf(secondCycles + sampleInSecond * cyclesPerSample)
}
