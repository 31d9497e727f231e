package org.hapticon.core.pattern

import kotlin.math.pow

/**
 * The pattern editor's three edits of a whole pattern, applied together to a copy named [name]:
 * - [gain] scales every amplitude key and every transient's intensity (0..1: an edit may only soften, so an
 *   edited pattern never drives harder than the file it came from);
 * - [semitones] moves the frequency curve by that many equal-tempered semitones (× 2^(s/12)), as a MIDI note
 *   moves an icon's carrier;
 * - [timeScale] stretches (> 1) or compresses (< 1) every key and transient time.
 *
 * Throws [PatternException] naming the edit (`gain`, `semitones`, `timeScale`) when it is not finite or out of
 * range, or the pattern's own field when the result breaks a pattern rule (the 30 s cap, the 20 kHz limit).
 */
public fun HapticPattern.edited(name: String, gain: Double = 1.0, semitones: Double = 0.0, timeScale: Double = 1.0): HapticPattern {
    if (!(gain in 0.0..1.0)) throw PatternException("gain", "must be in [0, 1], was $gain")
    if (!(semitones in -MAX_SEMITONES..MAX_SEMITONES)) throw PatternException("semitones", "must be in [-$MAX_SEMITONES, $MAX_SEMITONES], was $semitones")
    if (!(timeScale in MIN_TIME_SCALE..MAX_TIME_SCALE)) throw PatternException("timeScale", "must be in [$MIN_TIME_SCALE, $MAX_TIME_SCALE], was $timeScale")
    val ratio = 2.0.pow(semitones / 12.0)
    // The editor's result is played and sent, so it keeps the safety cap a stretched pattern could break.
    return HapticPattern(
        name,
        amplitude.map { AmplitudeKey(it.time * timeScale, it.amplitude * gain) },
        frequency.map { FrequencyKey(it.time * timeScale, it.hertz * ratio) },
        transients.map { Transient(it.time * timeScale, it.intensity * gain, it.sharpness) },
    ).checkPlayable()
}

/** Largest pitch move of [edited], in semitones (four octaves). */
public const val MAX_SEMITONES: Double = 48.0

/** Smallest time scale of [edited]. */
public const val MIN_TIME_SCALE: Double = 0.1

/** Largest time scale of [edited]; the 30 s cap still applies to the result. */
public const val MAX_TIME_SCALE: Double = 10.0
