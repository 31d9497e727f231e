package org.hapticon.core.pattern

import java.util.Locale
import kotlin.math.abs
import kotlin.math.ceil
import kotlin.math.floor
import kotlin.math.ln
import kotlin.math.pow

/**
 * What to do with carrier frequencies an actuator cannot give (outside the range its
 * `Vibrator.getFrequencyProfile()` reports on API 36). A user-visible choice, shown to the sender.
 */
public enum class PitchFit {
    /**
     * Move the whole pattern by the fewest whole octaves that bring its frequencies inside the range (as far as
     * they can go), keeping its contour and intervals (a note stays the same note name); then clamp whatever still
     * lies outside. The default: see docs/patterns.md, "Notes outside the actuator's range".
     */
    OCTAVES,

    /** Clamp each frequency to the nearest end of the range. */
    CLAMP,
}

/**
 * A pattern fitted into an actuator's frequency range by [fitPitchInto].
 *
 * @property pattern the pattern to play.
 * @property octaves whole octaves the pattern was moved (negative = down); 0 for [PitchFit.CLAMP].
 * @property clampedKeys frequency keys that still had to be clamped to the range.
 * @property summary one sentence for the sender, e.g. "plays 1 octave lower (349.2 → 174.6 Hz) to fit 100–250 Hz".
 */
public data class FittedPitch(val pattern: HapticPattern, val octaves: Int, val clampedKeys: Int, val summary: String)

/**
 * This pattern with its frequency curve moved into [minHz]..[maxHz] by [fit]. The octave shift is the one that
 * leaves the least of the pattern's span outside the range (in octaves, below plus above), and among equally good
 * shifts the smallest, then the lower one: a pattern that fits is never moved, a single note moves by the fewest
 * octaves that bring it inside (349.2 Hz into 50–300 Hz: one octave down to 174.6 Hz, not two), and a note that no
 * shift brings inside a range narrower than an octave lands as close to it as it can before it is clamped.
 *
 * @throws IllegalArgumentException if the range is not finite, positive and increasing.
 */
public fun HapticPattern.fitPitchInto(minHz: Double, maxHz: Double, fit: PitchFit = PitchFit.OCTAVES): FittedPitch {
    require(minHz.isFinite() && maxHz.isFinite() && minHz > 0.0 && maxHz > minHz) { "range must satisfy 0 < minHz < maxHz, was $minHz..$maxHz" }
    val lowest = frequency.minOf { it.hertz }
    val highest = frequency.maxOf { it.hertz }
    val range = String.format(Locale.ROOT, "%.0f–%.0f Hz", minHz, maxHz)
    if (lowest >= minHz && highest <= maxHz) return FittedPitch(this, 0, 0, "plays at its own pitch; $range covers it")
    val octaves = if (fit == PitchFit.OCTAVES) fewestOctaves(lowest, highest, minHz, maxHz) else 0
    val factor = 2.0.pow(octaves)
    var clamped = 0
    val moved = frequency.map { key ->
        val hz = key.hertz * factor
        val inside = hz.coerceIn(minHz, maxHz)
        if (inside != hz) clamped++
        FrequencyKey(key.time, inside)
    }
    val what = when {
        octaves == 0 -> "clamped to $range"
        else -> String.format(Locale.ROOT, "plays %d octave%s %s (%.1f → %.1f Hz) to fit %s", abs(octaves),
            if (abs(octaves) == 1) "" else "s", if (octaves < 0) "lower" else "higher", frequency.first().hertz, moved.first().hertz, range)
    }
    val rest = if (octaves != 0 && clamped > 0) "; $clamped frequency key${if (clamped == 1) "" else "s"} still clamped" else ""
    return FittedPitch(HapticPattern(name, amplitude, moved, transients), octaves, clamped, what + rest)
}

// The shift k (octaves) minimising how far [lowest·2^k, highest·2^k] sticks out of [minHz, maxHz], in octaves; ties go
// to the smaller |k|, then to the lower k. The overhang is convex in k, so scanning the shifts that can matter is exact.
private fun fewestOctaves(lowest: Double, highest: Double, minHz: Double, maxHz: Double): Int {
    fun log2(x: Double) = ln(x) / ln(2.0)
    fun overhang(k: Int): Double {
        val low = log2(lowest) + k
        val high = log2(highest) + k
        return maxOf(0.0, log2(minHz) - low) + maxOf(0.0, high - log2(maxHz))
    }
    val from = floor(log2(minHz / highest)).toInt() - 1
    val to = ceil(log2(maxHz / lowest)).toInt() + 1
    return (from..to).minWith(compareBy<Int>({ overhang(it) }, { abs(it) }, { it }))
}
