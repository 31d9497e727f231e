package org.hapticon.core.render

/**
 * A [SampleStream] over samples already in memory (a recording, generated noise), for [org.hapticon.core.io.WavWriter].
 * The array is read as it is, not copied: do not change it while the stream is read.
 */
public class FloatArraySampleStream(private val samples: FloatArray, override val sampleRate: Int) : SampleStream {
    init {
        require(sampleRate > 0) { "sample rate must be > 0 Hz, was $sampleRate" }
    }

    override val totalSamples: Long get() = samples.size.toLong()

    override var position: Long = 0
        private set

    override fun read(destination: FloatArray, offset: Int, length: Int): Int {
        if (position >= samples.size) return -1
        val count = minOf(length.toLong(), samples.size - position).toInt()
        System.arraycopy(samples, position.toInt(), destination, offset, count)
        position += count
        return count
    }
}
