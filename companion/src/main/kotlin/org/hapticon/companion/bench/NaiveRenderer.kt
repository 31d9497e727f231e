package org.hapticon.companion.bench

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.envelope
import kotlin.math.PI
import kotlin.math.sin

/**
 * The baseline the bench compares against: what one would write first. For each sample i,
 * t = i / fs and the sample is sin(2π·f·t) · envelope(t), with the icon's continuous envelope
 * ([envelope], built once) sampled per call. Same sample count as the real renderer.
 */
class NaiveRenderer(icon: HapticIcon, private val sampleRate: Int, model: EnvelopeModel) {
    private val envelope = icon.envelope(model)
    private val angularFrequency = 2.0 * PI * icon.frequency
    val sampleCount: Long = Math.round(icon.duration * sampleRate)
    private var position = 0L

    /** Fills [block] with the next samples and returns how many, or -1 at the end, like a SampleStream. */
    fun read(block: FloatArray): Int {
        if (position >= sampleCount) return -1
        val count = minOf(block.size.toLong(), sampleCount - position).toInt()
        for (j in 0 until count) {
            val t = (position + j).toDouble() / sampleRate
            block[j] = (sin(angularFrequency * t) * envelope.sample(t)).toFloat()
        }
        position += count
        return count
    }
}
