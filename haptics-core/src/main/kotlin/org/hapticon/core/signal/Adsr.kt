package org.hapticon.core.signal

/**
 * Attack-decay-sustain-release envelope: 0 → [peak] over [attack], [peak] → [level] over [decay],
 * [level] for [sustain], [level] → 0 over [release] (seconds, all linear). Zero-length segments are
 * skipped.
 *
 * @property attack seconds from 0 to [peak].
 * @property decay seconds from [peak] to [level].
 * @property sustain seconds held at [level].
 * @property release seconds from [level] to 0.
 * @property peak the amplitude at the end of the attack.
 * @property level the sustained amplitude.
 * @throws IllegalArgumentException if a duration is negative or not finite, or an amplitude is not finite.
 */
public class Adsr(
    public val attack: Double,
    public val decay: Double,
    public val sustain: Double,
    public val release: Double,
    public val peak: Double = 1.0,
    public val level: Double = 0.5,
) : Envelope(adsrKeys(attack, decay, sustain, release, peak, level))

private fun adsrKeys(
    attack: Double,
    decay: Double,
    sustain: Double,
    release: Double,
    peak: Double,
    level: Double,
): List<Envelope.Key> {
    requireDurations(attack, decay, sustain, release)
    require(peak.isFinite() && level.isFinite()) { "amplitudes must be finite, were $peak and $level" }
    return listOf(
        Envelope.Key(0.0, 0.0),
        Envelope.Key(attack, peak),
        Envelope.Key(attack + decay, level),
        Envelope.Key(attack + decay + sustain, level),
        Envelope.Key(attack + decay + sustain + release, 0.0),
    )
}
