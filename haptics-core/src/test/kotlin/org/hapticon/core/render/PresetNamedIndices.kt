package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import kotlin.math.ceil

/** Named sample indices of a preset render, computed from the icon's parameters and the documented boundary rules. */
internal fun presetNamedIndices(icon: HapticIcon, model: EnvelopeModel, sampleRate: Int): Map<String, Long> {
    val fs = sampleRate.toDouble()
    val count = Math.round(icon.duration * fs)
    val attackEnd: Long
    val releaseStart: Long
    when (model) {
        EnvelopeModel.PAPER -> {
            attackEnd = ceil(icon.attack * fs).toLong()
            releaseStart = ceil((icon.attack + icon.sustain) * fs).toLong()
        }
        EnvelopeModel.PROCESSING -> {
            attackEnd = Math.round(icon.attack * fs)
            releaseStart = Math.round((icon.attack + icon.sustain) * fs)
        }
    }
    val names = linkedMapOf(
        "first" to 0L,
        "second" to 1L,
        "last attack sample" to attackEnd - 1,
        "first sustain sample" to attackEnd,
        "mid sustain" to Math.round((icon.attack + icon.sustain / 2) * fs),
        "first release sample" to releaseStart,
        "last sample" to count - 1,
    )
    if (icon.count > 1) names["second onset"] = Math.round(icon.period * fs)
    if (icon == HapticIcon.STROKE) names["overlap at 2.8 s"] = Math.round(2.8 * fs)
    return names
}
