package org.hapticon.core.pattern

import org.hapticon.core.midiNoteToHz
import kotlin.math.ln
import kotlin.math.pow
import kotlin.math.sqrt

/**
 * The one mapping between the three ways haptic formats name a carrier: Hz (Hapticon, Android's
 * `WaveformEnvelopeBuilder`), a normalised frequency 0..1 (Meta `.haptic` frequency breakpoints, Android's
 * `BasicEnvelopeBuilder` sharpness) and Apple's sharpness 0..1 (AHAP).
 *
 * - Normalised ↔ Hz is logarithmic over the range [minHz, maxHz]: `hz = minHz · (maxHz/minHz)^x`, so equal
 *   steps of x are equal musical intervals, as MIDI notes are (the default range makes x linear in the note).
 * - Sharpness ↔ normalised follows Meta's own `.haptic` → AHAP converter: `sharpness = sqrt(frequency)`
 *   (Lofelt/NiceVibrations `core/datamodel/src/ios/v1.rs`, the `HapticSharpnessControl` curve built from
 *   the frequency envelope), hence `frequency = sharpness²`.
 *
 * The range is an input: a phone's actuator reports its own through `Vibrator.getFrequencyProfile()` (API 36);
 * files carry no range, so reading and writing them uses [DEFAULT] unless told otherwise.
 *
 * @throws IllegalArgumentException if the range is not finite, not positive or not increasing.
 */
public data class FrequencyMapping(val minHz: Double, val maxHz: Double) {
    init {
        require(minHz.isFinite() && maxHz.isFinite() && minHz > 0.0 && maxHz > minHz) {
            "frequency range must be finite with 0 < minHz < maxHz, was $minHz..$maxHz"
        }
    }

    /** Hz of normalised frequency [normalized], clamped to [0, 1] first (NaN counts as 0). */
    public fun hertzOf(normalized: Double): Double = minHz * (maxHz / minHz).pow(clamp01(normalized))

    /** Normalised frequency 0..1 of [hertz]; frequencies outside the range clamp to its ends. */
    public fun normalizedOf(hertz: Double): Double =
        if (!(hertz > minHz)) 0.0 else if (hertz >= maxHz) 1.0 else ln(hertz / minHz) / ln(maxHz / minHz)

    /** Hz of Apple sharpness [sharpness] (0..1, clamped): `hertzOf(sharpness²)`. */
    public fun hertzOfSharpness(sharpness: Double): Double = hertzOf(normalizedOfSharpness(sharpness))

    /** Apple sharpness 0..1 of [hertz]: `sqrt(normalizedOf(hertz))`. */
    public fun sharpnessOf(hertz: Double): Double = sharpnessOfNormalized(normalizedOf(hertz))

    /** Whether [hertz] lies inside the range (ends included). */
    public operator fun contains(hertz: Double): Boolean = hertz in minHz..maxHz

    public companion object {
        /**
         * C2..C5 (MIDI notes 36..72, 65.4..523.3 Hz): three octaves around a phone LRA's band that hold every
         * preset's note (50, 57, 65), with x = (note − 36)/36 exactly.
         */
        public val DEFAULT: FrequencyMapping = FrequencyMapping(midiNoteToHz(36.0), midiNoteToHz(72.0))

        /** Meta's frequency of Apple [sharpness]: sharpness², clamped to [0, 1]. */
        public fun normalizedOfSharpness(sharpness: Double): Double = clamp01(sharpness).let { it * it }

        /** Apple sharpness of Meta's normalised [frequency]: sqrt, clamped to [0, 1]. */
        public fun sharpnessOfNormalized(frequency: Double): Double = sqrt(clamp01(frequency))
    }
}

internal fun clamp01(x: Double): Double = if (!(x > 0.0)) 0.0 else if (x > 1.0) 1.0 else x
