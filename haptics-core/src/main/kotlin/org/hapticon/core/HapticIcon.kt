package org.hapticon.core

import java.util.Locale
import kotlin.math.pow

/**
 * A haptic icon: a sine carrier at MIDI [note] shaped by an attack/sustain/release envelope,
 * played [count] times with onset-to-onset [period] seconds.
 *
 * Durations are in seconds, [level] is the sustain amplitude in [0, 1], [note] may be fractional.
 * A value is always valid: the constructor throws [IconValidationException] naming the first bad field.
 * Limits that depend on the output rate (the carrier must stay below Nyquist) are checked by
 * [requireRenderableAt].
 */
public data class HapticIcon(
    val name: String,
    val attack: Double,
    val sustain: Double,
    val level: Double,
    val release: Double,
    val note: Double,
    val period: Double = 0.0,
    val count: Int = 1,
) {
    init {
        requireField(name.isNotBlank() && name.length <= MAX_NAME_LENGTH, "name") {
            "must be 1..$MAX_NAME_LENGTH characters, not blank"
        }
        requireDuration(attack, "attack")
        requireDuration(sustain, "sustain")
        requireDuration(release, "release")
        requireField(level.isFinite() && level in 0.0..1.0, "level") { "must be in [0, 1], was $level" }
        requireField(note.isFinite() && note in 0.0..127.0, "note") { "must be a MIDI note in [0, 127], was $note" }
        requireField(count in 1..MAX_COUNT, "count") { "must be in 1..$MAX_COUNT, was $count" }
        requireField(period.isFinite() && period >= 0.0, "period") { "must be a finite number of seconds >= 0, was $period" }
        requireField(count == 1 || period > 0.0, "period") { "must be > 0 when count > 1, was $period" }
        requireField(duration <= MAX_DURATION_SECONDS, "duration") {
            "total duration ${"%.3f".format(Locale.ROOT, duration)} s exceeds the ${MAX_DURATION_SECONDS} s safety cap"
        }
    }

    /**
     * Carrier frequency in Hz: 440·2^((note − 69)/12), the originating study's note formula solved for f
     * (000_f26496a15a0d284b.txt:78-81). Its Table 3 prints these rounded: 350, 220, 220 and 147 Hz for notes 65, 57,
     * 57 and 50 (:88-91), which are 349.23, 220.00, 220.00 and 146.83 Hz.
     */
    val frequency: Double get() = midiNoteToHz(note)

    /** Length of one envelope, attack + sustain + release, in seconds. */
    val envelopeDuration: Double get() = attack + sustain + release

    /** Total duration in seconds: (count − 1)·period + attack + sustain + release. */
    val duration: Double get() = (count - 1) * period + envelopeDuration

    /**
     * Throws [IconValidationException] (field `note`) when the carrier is at or above the Nyquist
     * frequency of [sampleRate], or (field `sampleRate`) when the rate is outside
     * [MIN_SAMPLE_RATE]..[MAX_SAMPLE_RATE].
     */
    public fun requireRenderableAt(sampleRate: Int) {
        requireField(sampleRate in MIN_SAMPLE_RATE..MAX_SAMPLE_RATE, "sampleRate") {
            "must be in $MIN_SAMPLE_RATE..$MAX_SAMPLE_RATE Hz, was $sampleRate"
        }
        requireField(frequency < sampleRate / 2.0, "note") {
            "carrier ${"%.2f".format(Locale.ROOT, frequency)} Hz (note $note) is at or above the Nyquist frequency " +
                "${sampleRate / 2} Hz of a $sampleRate Hz render"
        }
    }

    public companion object {
        /** Hard safety cap on how long one icon may drive the actuator. */
        public const val MAX_DURATION_SECONDS: Double = 30.0
        /** Most repetitions one icon may have. */
        public const val MAX_COUNT: Int = 64
        /** Longest icon name. */
        public const val MAX_NAME_LENGTH: Int = 64
        /** Lowest supported render rate in Hz. */
        public const val MIN_SAMPLE_RATE: Int = 8_000
        /** Highest supported render rate in Hz. */
        public const val MAX_SAMPLE_RATE: Int = 192_000

        /** Stroke, the originating study's Table 3: 1.0/1.0/0.3/1.0 s, note 65, period 2.6 s, ×4 (000_f26496a15a0d284b.txt:88). */
        public val STROKE: HapticIcon = HapticIcon("stroke", 1.0, 1.0, 0.3, 1.0, 65.0, 2.6, 4)
        /** Hit: 0.01/0.1/1.0/0.03 s, note 57, period 0.2 s, ×8 (000_f26496a15a0d284b.txt:89). */
        public val HIT: HapticIcon = HapticIcon("hit", 0.01, 0.1, 1.0, 0.03, 57.0, 0.2, 8)
        /** Knock: 0.005/0.01/0.5/0.005 s, note 57, period 0.27 s, ×3 (000_f26496a15a0d284b.txt:90). */
        public val KNOCK: HapticIcon = HapticIcon("knock", 0.005, 0.01, 0.5, 0.005, 57.0, 0.27, 3)
        /** Hug: 1.5/1.0/0.5/0.5 s, note 50, played once (period "-", 000_f26496a15a0d284b.txt:91). */
        public val HUG: HapticIcon = HapticIcon("hug", 1.5, 1.0, 0.5, 0.5, 50.0, 0.0, 1)

        /**
         * The longest icon the safety caps allow, and the busiest envelope: [MAX_COUNT] repetitions
         * lasting exactly [MAX_DURATION_SECONDS] (63 · 0.4375 + 3 · 0.8125 = 30 s, every term exact in
         * binary), attack/sustain/release 0.8125 s at level 0.7, note 69 (440 Hz), period 0.4375 s.
         * Its 2.4375 s envelopes overlap up to six at a time. The worst case for rendering cost, shared by
         * the benchmark and the tests so they measure the same icon. Not a preset.
         */
        public val LONGEST_ALLOWED: HapticIcon = HapticIcon("longest", 0.8125, 0.8125, 0.7, 0.8125, 69.0, 0.4375, 64)

        /** The four presets in the study's order: stroke, hit, knock, hug. */
        public val PRESETS: List<HapticIcon> = listOf(STROKE, HIT, KNOCK, HUG)

        /** The preset called [name] (case-insensitive), or null. */
        public fun preset(name: String): HapticIcon? = PRESETS.firstOrNull { it.name.equals(name, ignoreCase = true) }
    }
}

/** Frequency in Hz of MIDI [note] (A4 = note 69 = 440 Hz); fractional notes are allowed. */
public fun midiNoteToHz(note: Double): Double = 440.0 * 2.0.pow((note - 69.0) / 12.0)

/** An icon parameter is out of range; [field] names it as in the icon JSON schema. */
public class IconValidationException(public val field: String, message: String) :
    IllegalArgumentException("$field: $message")

private inline fun requireField(ok: Boolean, field: String, message: () -> String) {
    if (!ok) throw IconValidationException(field, message())
}

private fun requireDuration(seconds: Double, field: String) =
    requireField(seconds.isFinite() && seconds >= 0.0, field) { "must be a finite number of seconds >= 0, was $seconds" }
