package org.hapticon.app.ui

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.envelope

/**
 * The icon's amplitude envelope sampled at [points] evenly spaced times from 0 to its duration
 * (both ends included): enough to draw a thumbnail, without rendering any audio.
 */
fun envelopeOutline(icon: HapticIcon, points: Int, model: EnvelopeModel = EnvelopeModel.DEFAULT): FloatArray {
    require(points >= 2) { "an outline needs at least 2 points, was $points" }
    val envelope = icon.envelope(model)
    val duration = icon.duration
    return FloatArray(points) { i -> envelope.sample(duration * i / (points - 1)).toFloat() }
}
