package org.hapticon.core.pattern

import java.util.Locale
import kotlin.math.ln
import kotlin.math.pow
import kotlin.math.roundToInt

/**
 * What to do with carrier frequencies an actuator cannot give (outside the range its
 * `Vibrator.getFrequencyProfile()` reports on API 36). A user-visible choice, shown to the sender.
 */
public enum class PitchFit {
    /**
     * Move the whole pattern by whole octaves so that its frequencies sit inside the range as far as they can,
     * keeping its contour (a note stays the same note name); then clamp whatever still lies outside.
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
 * brings the geometric centre of the pattern's frequencies closest to the range's geometric centre, so a
 * pattern that fits is never moved.
 *
 * @throws IllegalArgumentException if the range is not finite, positive and increasing.
 */
public fun HapticPattern.fitPitchInto(minHz: Double, maxHz: Double, fit: PitchFit = PitchFit.OCTAVES): FittedPitch {
    require(minHz.isFinite() && maxHz.isFinite() && minHz > 0.0 && maxHz > minHz) { "range must satisfy 0 < minHz < maxHz, was $minHz..$maxHz" }
    val lowest = frequency.minOf { it.hertz }
    val highest = frequency.maxOf { it.hertz }
    val range = String.format(Locale.ROOT, "%.0f–%.0f Hz", minHz, maxHz)
    if (lowest >= minHz && highest <= maxHz) return FittedPitch(this, 0, 0, "plays at its own pitch; $range covers it")
    val octaves = if (fit == PitchFit.OCTAVES) {
        val centre = ln(lowest * highest) / 2
        val target = ln(minHz * maxHz) / 2
        ((target - centre) / ln(2.0)).roundToInt()
    } else {
        0
    }
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
        else -> String.format(Locale.ROOT, "plays %d octave%s %s (%.1f → %.1f Hz) to fit %s", kotlin.math.abs(octaves),
            if (kotlin.math.abs(octaves) == 1) "" else "s", if (octaves < 0) "lower" else "higher", frequency.first().hertz, moved.first().hertz, range)
    }
    val rest = if (octaves != 0 && clamped > 0) "; $clamped frequency key${if (clamped == 1) "" else "s"} still clamped" else ""
    return FittedPitch(HapticPattern(name, amplitude, moved, transients), octaves, clamped, what + rest)
}
