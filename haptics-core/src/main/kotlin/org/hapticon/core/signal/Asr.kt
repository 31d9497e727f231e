package org.hapticon.core.signal

/**
 * Attack-sustain-release envelope: 0 → [level] linearly over [attack] seconds, [level] for
 * [sustain] seconds, [level] → 0 linearly over [release] seconds. Zero-length segments are
 * skipped, so `attack = 0` starts at [level].
 *
 * @property attack seconds from 0 to [level].
 * @property sustain seconds held at [level].
 * @property release seconds from [level] to 0.
 * @property level the sustained amplitude.
 * @throws IllegalArgumentException if a duration is negative or not finite, or [level] is not finite.
 */
public class Asr(
    public val attack: Double,
    public val sustain: Double,
    public val release: Double,
    public val level: Double = 1.0,
) : Envelope(asrKeys(attack, sustain, release, level))

private fun asrKeys(attack: Double, sustain: Double, release: Double, level: Double): List<Envelope.Key> {
    requireDurations(attack, sustain, release)
    require(level.isFinite()) { "level must be finite, was $level" }
    return listOf(
        Envelope.Key(0.0, 0.0),
        Envelope.Key(attack, level),
        Envelope.Key(attack + sustain, level),
        Envelope.Key(attack + sustain + release, 0.0),
    )
}

internal fun requireDurations(vararg seconds: Double) {
    for (s in seconds) require(s.isFinite() && s >= 0.0) { "durations must be finite and >= 0, was $s" }
}
