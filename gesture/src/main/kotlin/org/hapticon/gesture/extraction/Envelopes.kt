package org.hapticon.gesture.extraction

import kotlin.math.PI
import kotlin.math.abs
import kotlin.math.sqrt
import kotlin.math.tan

/** How the amplitude envelope of a channel is measured. */
public enum class EnvelopeMethod {
    /** Full-wave rectify, then a 2nd-order Butterworth low-pass run forward and backward (zero phase). */
    LOWPASS,

    /** Root mean square over a centred moving window. */
    RMS,
}

/**
 * Envelope detectors. Both return an array as long as the input, aligned with it (no delay), so onsets and
 * breakpoints found on the envelope are times in the recording.
 */
public object Envelopes {
    /**
     * [samples] filtered by a 2nd-order Butterworth low-pass at [cutoffHz] (bilinear transform), run forward
     * then backward: zero phase, so a ramp's corners are rounded symmetrically and a least-squares line
     * still finds them, and an effective 4th-order (−24 dB/octave) magnitude. Each pass starts in the steady
     * state of its first input sample, so a recording that begins or ends mid-gesture has no start-up
     * transient. With [rectify], |x| is filtered instead of x (the mean of a rectified sine of amplitude A is
     * 2A/π; callers scale by π/2).
     */
    public fun lowpass(samples: DoubleArray, sampleRate: Double, cutoffHz: Double, rectify: Boolean): DoubleArray {
        require(sampleRate.isFinite() && sampleRate > 0.0) { "sample rate must be finite and > 0 Hz, was $sampleRate" }
        require(cutoffHz.isFinite() && cutoffHz > 0.0 && cutoffHz < sampleRate / 2.0) {
            "low-pass cutoff must be in (0, ${sampleRate / 2.0}) Hz (below Nyquist), was $cutoffHz"
        }
        val out = DoubleArray(samples.size) { if (rectify) abs(samples[it]) else samples[it] }
        if (out.isEmpty()) return out
        val k = tan(PI * cutoffHz / sampleRate)
        val norm = 1.0 / (1.0 + SQRT2 * k + k * k)
        val b0 = k * k * norm
        val a1 = 2.0 * (k * k - 1.0) * norm
        val a2 = (1.0 - SQRT2 * k + k * k) * norm
        biquadPass(out, b0, a1, a2, forward = true)
        biquadPass(out, b0, a1, a2, forward = false)
        return out
    }

    /**
     * Moving RMS of [samples] over a centred window of [windowSamples] (odd windows are centred exactly;
     * near the ends the window shrinks to the samples that exist). O(n): a running sum of squares, summed
     * afresh every [RESUM_INTERVAL] steps so rounding cannot drift over hour-long inputs.
     */
    public fun rms(samples: DoubleArray, windowSamples: Int): DoubleArray {
        require(windowSamples >= 1) { "RMS window must be at least 1 sample, was $windowSamples" }
        val n = samples.size
        val out = DoubleArray(n)
        if (n == 0) return out
        val before = windowSamples / 2
        val after = windowSamples - 1 - before
        var lo = 0
        var hi = 0 // inclusive; both reset at i = 0, which re-sums
        var sum = 0.0
        for (i in 0 until n) {
            val newLo = maxOf(0, i - before)
            val newHi = minOf(n - 1, i + after)
            if (i % RESUM_INTERVAL == 0) {
                sum = 0.0
                for (j in newLo..newHi) sum += samples[j] * samples[j]
            } else {
                while (hi < newHi) { hi++; sum += samples[hi] * samples[hi] }
                while (lo < newLo) { sum -= samples[lo] * samples[lo]; lo++ }
            }
            lo = newLo
            hi = newHi
            out[i] = sqrt(maxOf(0.0, sum) / (newHi - newLo + 1))
        }
        return out
    }

    /** Steps between exact re-summations in [rms]. */
    public const val RESUM_INTERVAL: Int = 4096

    private const val SQRT2 = 1.4142135623730951

    // Direct form I of b0·(1, 2, 1) / (1, a1, a2), in place, over [data] in one direction.
    private fun biquadPass(data: DoubleArray, b0: Double, a1: Double, a2: Double, forward: Boolean) {
        val n = data.size
        val first = if (forward) data[0] else data[n - 1]
        var x1 = first
        var x2 = first
        var y1 = first
        var y2 = first
        for (step in 0 until n) {
            val i = if (forward) step else n - 1 - step
            val x0 = data[i]
            val y0 = b0 * (x0 + 2.0 * x1 + x2) - a1 * y1 - a2 * y2
            data[i] = y0
            x2 = x1; x1 = x0
            y2 = y1; y1 = y0
        }
    }
}
