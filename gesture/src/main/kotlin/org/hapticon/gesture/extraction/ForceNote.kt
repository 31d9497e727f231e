package org.hapticon.gesture.extraction

import kotlin.math.ln
import kotlin.math.roundToInt

/**
 * The note of a force-only gesture (FSR, glove: no vibration carrier to measure). Firmer and shorter
 * contacts map to higher notes:
 *
 *     firmness  f = clamp(peak force / [FULL_FORCE_NEWTONS], 0, 1)
 *     length    d = clamp(log(contact / [SHORTEST_CONTACT_S]) / log([LONGEST_CONTACT_S] / [SHORTEST_CONTACT_S]), 0, 1)
 *     note      = round([LOWEST_NOTE] + ([HIGHEST_NOTE] − [LOWEST_NOTE]) · (f + (1 − d)) / 2)
 *
 * Why: the notes span 110–440 Hz, the band where the skin's Pacinian receptors are most sensitive and where
 * phone actuators respond. Within it higher frequencies feel sharper and lower ones softer, so a brief firm
 * tap (a knock) becomes a crisp high buzz and a long gentle press (a hug) a soft low one. Contact time is
 * taken on a log scale (10 ms .. 3 s) because taps and presses differ by orders of magnitude.
 */
public object ForceNote {
    /** Lowest mapped note: A2, 110 Hz. */
    public const val LOWEST_NOTE: Int = 45
    /** Highest mapped note: A4, 440 Hz. */
    public const val HIGHEST_NOTE: Int = 69
    /** Force that counts as fully firm, in newtons: a hard finger press on an FSR. */
    public const val FULL_FORCE_NEWTONS: Double = 20.0
    /** Contact time that counts as the shortest (a tap). */
    public const val SHORTEST_CONTACT_S: Double = 0.01
    /** Contact time that counts as the longest (a hold). */
    public const val LONGEST_CONTACT_S: Double = 3.0

    /**
     * The note for [firmness] in 0..1 (peak force relative to full; see [firmnessOf]) and contact time
     * [contactSeconds] (attack + sustain + release of one repetition).
     */
    public fun note(firmness: Double, contactSeconds: Double): Int {
        require(firmness.isFinite()) { "firmness must be finite, was $firmness" }
        require(contactSeconds.isFinite() && contactSeconds >= 0.0) { "contact time must be finite and >= 0 s, was $contactSeconds" }
        val f = firmness.coerceIn(0.0, 1.0)
        val d = (ln(maxOf(contactSeconds, SHORTEST_CONTACT_S) / SHORTEST_CONTACT_S) / ln(LONGEST_CONTACT_S / SHORTEST_CONTACT_S)).coerceIn(0.0, 1.0)
        return (LOWEST_NOTE + (HIGHEST_NOTE - LOWEST_NOTE) * (f + (1.0 - d)) / 2.0).roundToInt()
    }

    /**
     * Firmness of a press whose peak is [peak] in [unit]: newtons over [FULL_FORCE_NEWTONS]; a unit-less
     * (normalised) channel is already 0..1. Other units have no known full scale: null, and the caller
     * assumes 0.5 and warns.
     */
    public fun firmnessOf(peak: Double, unit: String): Double? = when (unit) {
        "N" -> (peak / FULL_FORCE_NEWTONS).coerceIn(0.0, 1.0)
        "" -> peak.coerceIn(0.0, 1.0)
        else -> null
    }
}
