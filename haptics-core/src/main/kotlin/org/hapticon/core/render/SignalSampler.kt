package org.hapticon.core.render

import org.hapticon.core.signal.Signal

/**
 * Samples this signal into a [SampleStream]: sample i is `sample(i / sampleRate)` and there are
 * round(length · sampleRate) samples (half up). Values are clamped to [-1, 1] to honour the
 * [SampleStream] contract (a pattern's bursts can add up past 1); NaN becomes 0, as in [Pcm16].
 *
 * The stream is the one every render is read through ([SampleSourceStream]); only the source differs:
 * here the signal at each sample's time, for an icon its [IconRenderer]'s run-by-run, phase-exact synthesizer.
 *
 * @throws IllegalArgumentException if [sampleRate] is not positive or the length is not finite.
 */
public fun Signal.stream(sampleRate: Int): SampleStream {
    require(sampleRate > 0) { "sampleRate must be positive, was $sampleRate" }
    require(length.isFinite() && length >= 0.0) { "only a finite signal can be streamed, length was $length" }
    return SampleSourceStream(SignalSource(this, sampleRate, Math.round(length * sampleRate)), sampleRate)
}

/** A [Signal] at i / [sampleRate] for sample i, clamped to [-1, 1], NaN as 0. */
private class SignalSource(private val signal: Signal, private val sampleRate: Int, override val totalSamples: Long) : SampleSource {
    override var position: Long = 0
        private set

    override fun fill(destination: DoubleArray, offset: Int, length: Int): Int {
        val count = minOf(length.toLong(), totalSamples - position).toInt()
        for (j in 0 until count) {
            val value = signal.sample((position + j).toDouble() / sampleRate)
            destination[offset + j] = if (value.isNaN()) 0.0 else value.coerceIn(-1.0, 1.0)
        }
        position += count
        return count
    }
}
