package org.hapticon.core.render

/**
 * [DoubleSampleStream] over an [IconSynthesizer]. FAST float reads narrow in the kernel; EXACT float
 * reads make samples as doubles in a fixed scratch block (allocated once per stream) and narrow them; double reads write straight into the
 * caller's array. Neither allocates.
 */
internal class IconSampleStream(
    private val synthesizer: IconSynthesizer,
    override val sampleRate: Int,
) : DoubleSampleStream {
    private val blocks = ScratchBlockReader(synthesizer)

    override val totalSamples: Long get() = synthesizer.totalSamples
    override val position: Long get() = synthesizer.position

    override fun read(destination: FloatArray, offset: Int, length: Int): Int {
        checkRange(destination.size, offset, length)
        if (position >= totalSamples) return -1
        if (synthesizer.mode == RenderMode.FAST) return synthesizer.fillFloats(destination, offset, length)
        return blocks.read(length) { scratch, written, made ->
            for (j in 0 until made) destination[offset + written + j] = scratch[j].toFloat()
        }
    }

    override fun read(destination: DoubleArray, offset: Int, length: Int): Int {
        checkRange(destination.size, offset, length)
        if (position >= totalSamples) return -1
        return synthesizer.fill(destination, offset, length)
    }
}

/** Throws [IndexOutOfBoundsException] unless [offset, offset + length) lies within an array of [size]. */
internal fun checkRange(size: Int, offset: Int, length: Int) {
    if (offset < 0 || length < 0 || offset > size - length) {
        throw IndexOutOfBoundsException("offset $offset and length $length do not fit an array of $size")
    }
}
