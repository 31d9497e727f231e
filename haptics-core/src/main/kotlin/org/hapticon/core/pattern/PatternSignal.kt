package org.hapticon.core.pattern

import org.hapticon.core.signal.Signal
import org.hapticon.core.signal.fractionOf
import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.sin

/**
 * [pattern] as a [Signal] (so `pattern.signal().stream(rate)` renders it like any other signal):
 * `amplitude(t) · sin(2π·φ(t))` plus every transient's burst, where φ is the integral of the frequency curve.
 *
 * The phase is exact for the piecewise-linear frequency curve: within a segment from key i,
 * φ = φᵢ + fᵢ·τ + (fᵢ₊₁ − fᵢ)·τ²/(2Δ), with φᵢ kept as a fraction of a cycle so that precision does not
 * decay along the pattern. A transient is a Hann-windowed sine burst of [Transient.DURATION_SECONDS] at
 * `mapping.hertzOfSharpness(sharpness)` with peak amplitude intensity² (the law of [Transient.intensity]) — our rendering, since neither Apple
 * nor Meta publishes one. The sum is not clamped here; [org.hapticon.core.render.stream] clamps to [-1, 1].
 */
public fun HapticPattern.signal(mapping: FrequencyMapping = FrequencyMapping.DEFAULT): Signal = PatternSignal(this, mapping)

private class PatternSignal(private val pattern: HapticPattern, mapping: FrequencyMapping) : Signal {
    private val keys = pattern.frequency
    private val keyTimes = DoubleArray(keys.size) { keys[it].time }
    // Cycles accumulated at each frequency key, as a fraction of a cycle.
    private val phaseAtKey = DoubleArray(keys.size).also { phase ->
        for (i in 1 until keys.size) {
            val span = keys[i].time - keys[i - 1].time
            phase[i] = fractionOf(phase[i - 1] + 0.5 * (keys[i - 1].hertz + keys[i].hertz) * span)
        }
    }
    private val tapTimes = DoubleArray(pattern.transients.size) { pattern.transients[it].time }
    private val tapHertz = DoubleArray(pattern.transients.size) { mapping.hertzOfSharpness(pattern.transients[it].sharpness) }

    override val length: Double = pattern.duration

    override fun sample(t: Double): Double {
        require(t.isFinite()) { "sample time must be finite, was $t" }
        if (t < 0.0 || t > length) return 0.0
        var value = 0.0
        val amplitude = pattern.amplitudeAt(t)
        if (amplitude > 0.0) value += amplitude * sin(2.0 * PI * cyclesAt(t))
        // Transients are sorted: walk back from the last one at or before t while their bursts still sound.
        var i = lastAtOrBefore(tapTimes, t)
        while (i >= 0 && t - tapTimes[i] < Transient.DURATION_SECONDS) {
            val tau = t - tapTimes[i]
            val window = 0.5 - 0.5 * cos(2.0 * PI * tau / Transient.DURATION_SECONDS)
            val peak = pattern.transients[i].intensity
            value += peak * peak * window * sin(2.0 * PI * fractionOf(tapHertz[i] * tau))
            i--
        }
        return value
    }

    private fun cyclesAt(t: Double): Double {
        val i = lastAtOrBefore(keyTimes, t)
        if (i < 0) return fractionOf(keys[0].hertz * t)
        val tau = t - keys[i].time
        if (i == keys.lastIndex) return fractionOf(phaseAtKey[i] + keys[i].hertz * tau)
        val span = keys[i + 1].time - keys[i].time
        val slope = (keys[i + 1].hertz - keys[i].hertz) / span
        return fractionOf(phaseAtKey[i] + keys[i].hertz * tau + 0.5 * slope * tau * tau)
    }
}

/** Index of the last element ≤ [t] in ascending [times]; −1 if none. */
private fun lastAtOrBefore(times: DoubleArray, t: Double): Int {
    var lo = 0
    var hi = times.size - 1
    var found = -1
    while (lo <= hi) {
        val mid = (lo + hi) ushr 1
        if (times[mid] <= t) {
            found = mid
            lo = mid + 1
        } else {
            hi = mid - 1
        }
    }
    return found
}
