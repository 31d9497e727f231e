package org.hapticon.core.render

/**
 * The one stream over a [SampleSource], for every sample type: doubles straight into the caller's array, floats
 * from the source's own float kernel or narrowed from a fixed double scratch block, PCM16 converted from that
 * block by [Pcm16.convert] (so values round only once). The scratch block is allocated once per stream; no
 * read allocates.
 */
internal class SampleSourceStream(
    private val source: SampleSource,
    override val sampleRate: Int,
) : DoubleSampleStream, PcmStream {
    private val scratch = DoubleArray(SCRATCH_SAMPLES)

    override val totalSamples: Long get() = source.totalSamples
    override val position: Long get() = source.position

    override fun read(destination: FloatArray, offset: Int, length: Int): Int {
        checkRange(destination.size, offset, length)
        if (position >= totalSamples) return -1
        if (source.hasFloatKernel) return source.fillFloats(destination, offset, length)
        return readBlocks(length) { written, made ->
            for (j in 0 until made) destination[offset + written + j] = scratch[j].toFloat()
        }
    }

    override fun read(destination: DoubleArray, offset: Int, length: Int): Int {
        checkRange(destination.size, offset, length)
        if (position >= totalSamples) return -1
        return source.fill(destination, offset, length)
    }

    override fun read(destination: ShortArray, offset: Int, length: Int): Int {
        checkRange(destination.size, offset, length)
        if (position >= totalSamples) return -1
        return readBlocks(length) { written, made -> Pcm16.convert(scratch, destination, 0, offset + written, made) }
    }

    /** Makes up to [length] samples in the scratch block, block by block, handing each to [convert] (samples so far, samples in it). */
    private inline fun readBlocks(length: Int, convert: (written: Int, made: Int) -> Unit): Int {
        var written = 0
        while (written < length) {
            val made = source.fill(scratch, 0, minOf(SCRATCH_SAMPLES, length - written))
            if (made == 0) break
            convert(written, made)
            written += made
        }
        return written
    }

    private companion object {
        const val SCRATCH_SAMPLES = 1024
    }
}

/** Throws [IndexOutOfBoundsException] unless [offset, offset + length) lies within an array of [size]. */
internal fun checkRange(size: Int, offset: Int, length: Int) {
    if (offset < 0 || length < 0 || offset > size - length) {
        throw IndexOutOfBoundsException("offset $offset and length $length do not fit an array of $size")
    }
}
