package org.hapticon.messaging

import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.render.RendererKind

/**
 * What a user's device can do with a haptic icon, published as a retained message at
 * [Topics.capabilities] so that a sender can see how its icons will be felt. A value is always valid: the
 * constructor throws [InvalidMessageException] naming the first bad field.
 *
 * @property user whose device this describes.
 * @property renderer how the device plays icons.
 * @property amplitudeControl whether its vibrator can vary strength (Android `Vibrator.hasAmplitudeControl()`).
 * @property apiLevel the Android API level, or null when the device is not an Android phone.
 * @property resonantFrequencyHz the actuator's resonant frequency when known (Android 12+), else null.
 * @property envelopeEffects whether the vibrator plays Android 16 envelope effects (`Vibrator.areEnvelopeEffectsSupported()`);
 *   null when the sender did not say (older builds, non-Android peers).
 * @property frequencyRangeHz the frequencies its envelope effects can play (API 36 `Vibrator.getFrequencyProfile()`
 *   min..max Hz), null without a frequency profile or when not said.
 * @property pitchFit what it does with frequencies outside [frequencyRangeHz] (its user's setting), null when not said
 *   (older builds play [PitchFit.OCTAVES]).
 * @property envelopeLimits what its envelope effects accept (API 36 `Vibrator.getEnvelopeEffectInfo()`: most control
 *   points, shortest and longest control point, longest effect), null without envelope effects or when not said (older
 *   builds); a sender then assumes [EnvelopeEffectInfo.GUARANTEED].
 */
public data class Capabilities(
    val user: String,
    val renderer: RendererKind,
    val amplitudeControl: Boolean,
    val apiLevel: Int? = null,
    val resonantFrequencyHz: Double? = null,
    val envelopeEffects: Boolean? = null,
    val frequencyRangeHz: ClosedFloatingPointRange<Double>? = null,
    val pitchFit: PitchFit? = null,
    val envelopeLimits: EnvelopeEffectInfo? = null,
) {
    init {
        check(Topics.isValidUserName(user), RejectionReason.INVALID_VALUE, "user") { "not a valid user name: ${quote(user)}" }
        if (apiLevel != null) {
            check(apiLevel in 1..MAX_API_LEVEL, RejectionReason.INVALID_VALUE, "apiLevel") { "expected 1..$MAX_API_LEVEL, got $apiLevel" }
        }
        if (resonantFrequencyHz != null) {
            check(
                resonantFrequencyHz.isFinite() && resonantFrequencyHz in 1.0..MAX_RESONANT_FREQUENCY_HZ,
                RejectionReason.INVALID_VALUE, "resonantFrequencyHz",
            ) { "expected a frequency in 1..$MAX_RESONANT_FREQUENCY_HZ Hz, got $resonantFrequencyHz" }
        }
        if (frequencyRangeHz != null) {
            val (min, max) = frequencyRangeHz.start to frequencyRangeHz.endInclusive
            check(
                min.isFinite() && max.isFinite() && min >= 1.0 && max <= MAX_RESONANT_FREQUENCY_HZ && min < max,
                RejectionReason.INVALID_VALUE, "frequencyMinHz",
            ) { "expected 1 ≤ frequencyMinHz < frequencyMaxHz ≤ $MAX_RESONANT_FREQUENCY_HZ Hz, got $min..$max" }
        }
        if (envelopeLimits != null) {
            val (points, min, max, total) = envelopeLimits
            check(points in 1..MAX_ENVELOPE_CONTROL_POINTS, RejectionReason.INVALID_VALUE, "envelopeMaxControlPoints") {
                "expected 1..$MAX_ENVELOPE_CONTROL_POINTS, got $points"
            }
            // Android's own invariant: maxDuration = maxSize × longest control point, so each bound holds the next.
            check(min >= 1 && min <= max, RejectionReason.INVALID_VALUE, "envelopeMinControlPointMillis") {
                "expected 1 ≤ envelopeMinControlPointMillis ≤ envelopeMaxControlPointMillis, got $min and $max"
            }
            check(max <= total && total <= MAX_ENVELOPE_MILLIS, RejectionReason.INVALID_VALUE, "envelopeMaxDurationMillis") {
                "expected envelopeMaxControlPointMillis ≤ envelopeMaxDurationMillis ≤ $MAX_ENVELOPE_MILLIS, got $max and $total"
            }
        }
    }

    public companion object {
        /** Highest API level accepted; far above any that exists, low enough to catch garbage. */
        public const val MAX_API_LEVEL: Int = 1_000

        /** Highest resonant frequency accepted, in Hz; phone actuators resonate around 150–250 Hz. */
        public const val MAX_RESONANT_FREQUENCY_HZ: Double = 2_000.0

        /** Most envelope control points accepted; Android guarantees 16, and more than this is garbage, not a phone. */
        public const val MAX_ENVELOPE_CONTROL_POINTS: Int = 1_000

        /** Longest envelope effect (and control point) accepted, in ms: 10 minutes, far above any vibrator's. */
        public const val MAX_ENVELOPE_MILLIS: Long = 600_000
    }
}
