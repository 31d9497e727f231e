package org.hapticon.core.pattern

import org.hapticon.core.HapticIcon
import java.util.Locale

/**
 * A haptic pattern: a continuous vibration whose amplitude and carrier frequency follow keyed curves,
 * plus transients (short taps). It is the general form of a [HapticIcon] (see [toPattern]) and the common
 * ground of Apple's AHAP ([Ahap]) and Meta's `.haptic` ([MetaHaptic]) files.
 *
 * - [amplitude]: drive amplitude 0..1 at each key, straight lines between keys, 0 after the last key.
 *   Its last key ends the continuous part.
 * - [frequency]: carrier frequency in Hz at each key, straight lines between keys, held before the first and
 *   after the last key. At least one key.
 * - [transients]: taps at their times; each is rendered as a [Transient.DURATION_SECONDS] burst.
 *
 * A value is always valid: the constructor throws [PatternException] naming the first bad field
 * (`amplitude[3].time: must not be before the previous key`), so no NaN, negative time or out-of-range
 * amplitude can reach an actuator. A value may last up to [MAX_DURATION_SECONDS] (an hour), because a file
 * converted from one format to another drives no body (Lofelt's and Meta's tools make clips over a minute long);
 * whatever plays or sends a pattern first asks [checkPlayable], which holds the 30 s safety cap of icons
 * ([HapticIcon.MAX_DURATION_SECONDS]).
 */
public class HapticPattern(
    public val name: String,
    amplitude: List<AmplitudeKey>,
    frequency: List<FrequencyKey>,
    transients: List<Transient> = emptyList(),
) {
    /** The amplitude curve's keys in time order (a copy). */
    public val amplitude: List<AmplitudeKey> = amplitude.toList()

    /** The frequency curve's keys in time order (a copy). */
    public val frequency: List<FrequencyKey> = frequency.toList()

    /** The transients in time order (a copy). */
    public val transients: List<Transient> = transients.toList()

    init {
        check(name.isNotBlank() && name.length <= HapticIcon.MAX_NAME_LENGTH, "name") {
            "must be 1..${HapticIcon.MAX_NAME_LENGTH} characters, not blank"
        }
        check(this.amplitude.size <= MAX_KEYS, "amplitude") { "has ${this.amplitude.size} keys; at most $MAX_KEYS" }
        check(this.frequency.size <= MAX_KEYS, "frequency") { "has ${this.frequency.size} keys; at most $MAX_KEYS" }
        check(this.transients.size <= MAX_KEYS, "transients") { "has ${this.transients.size} taps; at most $MAX_KEYS" }
        check(this.frequency.isNotEmpty(), "frequency") { "needs at least one key" }
        checkTimes("amplitude", this.amplitude.map { it.time })
        checkTimes("frequency", this.frequency.map { it.time })
        checkTimes("transients", this.transients.map { it.time })
        this.amplitude.forEachIndexed { i, key ->
            check(key.amplitude.isFinite() && key.amplitude in 0.0..1.0, "amplitude[$i].amplitude") {
                "must be in [0, 1], was ${key.amplitude}"
            }
        }
        this.frequency.forEachIndexed { i, key ->
            check(key.hertz.isFinite() && key.hertz > 0.0 && key.hertz <= MAX_HERTZ, "frequency[$i].hertz") {
                "must be in (0, $MAX_HERTZ] Hz, was ${key.hertz}"
            }
        }
        this.transients.forEachIndexed { i, tap ->
            check(tap.intensity.isFinite() && tap.intensity in 0.0..1.0, "transients[$i].intensity") {
                "must be in [0, 1], was ${tap.intensity}"
            }
            check(tap.sharpness.isFinite() && tap.sharpness in 0.0..1.0, "transients[$i].sharpness") {
                "must be in [0, 1], was ${tap.sharpness}"
            }
        }
        check(duration <= MAX_DURATION_SECONDS, "duration") {
            "total duration ${"%.3f".format(Locale.ROOT, duration)} s is longer than a pattern may be ($MAX_DURATION_SECONDS s)"
        }
    }

    /**
     * This pattern, when it may drive an actuator: throws [PatternException] on `duration` when it plays longer
     * than the [HapticIcon.MAX_DURATION_SECONDS] safety cap. Every path that vibrates, plays audio-coupled haptics
     * or imports a pattern into the app's library (whose patterns are there to be played and sent) calls it.
     */
    public fun checkPlayable(): HapticPattern {
        check(duration <= HapticIcon.MAX_DURATION_SECONDS, "duration") {
            "plays for ${"%.3f".format(Locale.ROOT, duration)} s, longer than the ${HapticIcon.MAX_DURATION_SECONDS} s safety cap for playing"
        }
        return this
    }

    /** Seconds the continuous part lasts: the last amplitude key's time (0 without keys). */
    public val continuousDuration: Double get() = amplitude.lastOrNull()?.time ?: 0.0

    /** Seconds until the last sound ends: the continuous part or the last transient's burst, whichever is later. */
    public val duration: Double
        get() = maxOf(continuousDuration, transients.lastOrNull()?.let { it.time + Transient.DURATION_SECONDS } ?: 0.0)

    /** The amplitude curve's value at [t] seconds: linear between keys, 0 before the first and after the last. */
    public fun amplitudeAt(t: Double): Double = interpolate(amplitude, t, outside = 0.0, time = { it.time }, value = { it.amplitude })

    /** The carrier frequency at [t] seconds: linear between keys, held before the first and after the last. */
    public fun frequencyAt(t: Double): Double = interpolate(frequency, t, outside = Double.NaN, time = { it.time }, value = { it.hertz })

    /** A copy named [name]. */
    public fun named(name: String): HapticPattern = HapticPattern(name, amplitude, frequency, transients)

    override fun equals(other: Any?): Boolean = other is HapticPattern && name == other.name &&
        amplitude == other.amplitude && frequency == other.frequency && transients == other.transients

    override fun hashCode(): Int = listOf(name, amplitude, frequency, transients).hashCode()

    override fun toString(): String =
        "HapticPattern($name, ${amplitude.size} amplitude keys, ${frequency.size} frequency keys, ${transients.size} transients)"

    public companion object {
        /** Most keys in one curve (and most transients): a bound on memory and on per-sample search. */
        public const val MAX_KEYS: Int = 4096

        /** Highest carrier frequency a pattern may ask for. */
        public const val MAX_HERTZ: Double = 20_000.0

        /**
         * Longest a pattern value may last, in seconds (one hour). Bounds what a conversion may write (an hour of
         * 48 kHz float WAV is 690 MB); far past the longest clip the haptic tools make.
         */
        public const val MAX_DURATION_SECONDS: Double = 3600.0
    }
}

/**
 * One corner of a pattern's amplitude curve.
 *
 * @property time seconds from the start of the pattern.
 * @property amplitude drive amplitude in [0, 1].
 */
public data class AmplitudeKey(val time: Double, val amplitude: Double)

/**
 * One corner of a pattern's frequency curve.
 *
 * @property time seconds from the start of the pattern.
 * @property hertz carrier frequency in Hz.
 */
public data class FrequencyKey(val time: Double, val hertz: Double)

/**
 * A short tap: AHAP's `HapticTransient`, a `.haptic` emphasis point.
 *
 * @property time seconds from the start of the pattern.
 * @property intensity strength in [0, 1] on Apple's intensity scale; the burst's peak amplitude is intensity²,
 *   the law Meta's converter uses between `.haptic` amplitude and AHAP intensity ([Ahap]).
 * @property sharpness 0 (round) to 1 (crisp); chooses the burst's carrier through [FrequencyMapping].
 */
public data class Transient(val time: Double, val intensity: Double, val sharpness: Double) {
    public companion object {
        /**
         * How long one rendered tap lasts: 20 ms. Neither Apple nor Meta publishes the waveform of a
         * transient, so ours is our choice, documented in docs/patterns.md: a Hann-windowed sine burst.
         */
        public const val DURATION_SECONDS: Double = 0.020
    }
}

/** A pattern or pattern file is invalid; [field] names the member, as in the file (`amplitude[2].time`). */
public class PatternException(public val field: String, message: String) : IllegalArgumentException("$field: $message")

private inline fun check(ok: Boolean, field: String, message: () -> String) {
    if (!ok) throw PatternException(field, message())
}

private fun checkTimes(field: String, times: List<Double>) {
    times.forEachIndexed { i, t ->
        check(t.isFinite() && t >= 0.0, "$field[$i].time") { "must be a finite number of seconds >= 0, was $t" }
        check(i == 0 || t >= times[i - 1], "$field[$i].time") { "must not be before the previous key (${times[i - 1]} s), was $t" }
    }
}

private inline fun <K> interpolate(keys: List<K>, t: Double, outside: Double, time: (K) -> Double, value: (K) -> Double): Double {
    require(t.isFinite()) { "time must be finite, was $t" }
    if (keys.isEmpty()) return 0.0
    if (t < time(keys[0])) return if (outside.isNaN()) value(keys[0]) else outside
    // Binary search for the last key at or before t, so that at a step the later key wins.
    var lo = 0
    var hi = keys.lastIndex
    while (lo < hi) {
        val mid = (lo + hi + 1) ushr 1
        if (time(keys[mid]) <= t) lo = mid else hi = mid - 1
    }
    if (lo == keys.lastIndex) {
        return if (t == time(keys[lo]) || outside.isNaN()) value(keys[lo]) else outside
    }
    val from = keys[lo]
    val to = keys[lo + 1]
    val span = time(to) - time(from)
    return value(from) + (value(to) - value(from)) * (t - time(from)) / span
}
