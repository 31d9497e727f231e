package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.hapticon.core.signal.Adsr
import org.hapticon.core.signal.Asr
import org.hapticon.core.signal.Overlap
import org.hapticon.core.signal.Repeater
import org.hapticon.core.signal.Signal

/**
 * The ideal (continuous-time) amplitude envelope of this icon over all its repetitions.
 *
 * - [EnvelopeModel.PAPER]: 0 → level over attack, level for sustain, level → 0 over release;
 *   zero-length segments are skipped (attack 0 starts at level).
 * - [EnvelopeModel.PROCESSING]: 0 → 1 over attack, 1 → level over sustain, level → 0 over release.
 *
 * Envelope k starts at k · period; overlapping envelopes combine by maximum ([Overlap.MAX]).
 * The length is [HapticIcon.duration]. [IconRenderer] renders the same shapes at sample resolution,
 * with each onset on the nearest sample and PROCESSING segments in whole samples; see [IconRenderer].
 */
public fun HapticIcon.envelope(model: EnvelopeModel = EnvelopeModel.PAPER): Signal {
    val single = when (model) {
        EnvelopeModel.PAPER -> Asr(attack, sustain, release, level)
        // Processing's "sustain" is a ramp from the attack peak 1 down to the level.
        EnvelopeModel.PROCESSING -> Adsr(attack, decay = sustain, sustain = 0.0, release = release, peak = 1.0, level = level)
    }
    return Repeater(single, count, period, Overlap.MAX)
}
