package org.hapticon.core.render

import org.hapticon.core.signal.Signal

/**
 * Samples this signal into a [SampleStream]: sample i is `sample(i / sampleRate)` and there are
 * round(length · sampleRate) samples (half up). Values are clamped to [-1, 1] to honour the
 * [SampleStream] contract (a [org.hapticon.core.signal.Sum] can exceed it); NaN becomes 0, as in [Pcm16].
 *
 * This is the general engine for any signal; [IconRenderer] is the fast, phase-exact path for icons.
 *
 * @throws IllegalArgumentException if [sampleRate] is not positive or the length is not finite.
 */
public fun Signal.stream(sampleRate: Int): SampleStream {
    require(sampleRate > 0) { "sampleRate must be positive, was $sampleRate" }
    require(length.isFinite() && length >= 0.0) { "only a finite signal can be streamed, length was $length" }
    return SignalSampleStream(this, sampleRate, Math.round(length * sampleRate))
}

private class SignalSampleStream(
    private val signal: Signal,
    override val sampleRate: Int,
    override val totalSamples: Long,
) : SampleStream {
    override var position: Long = 0
        private set

    override fun read(destination: FloatArray, offset: Int, length: Int): Int {
        checkRange(destination.size, offset, length)
        if (position >= totalSamples) return -1
        val count = minOf(length.toLong(), totalSamples - position).toInt()
        for (j in 0 until count) {
            val value = signal.sample((position + j).toDouble() / sampleRate)
            destination[offset + j] = if (value.isNaN()) 0f else value.coerceIn(-1.0, 1.0).toFloat()
        }
        position += count
        return count
    }
}
