package org.hapticon.core.render

/**
 * Makes a render's samples in order from sample 0, as doubles: what [SampleSourceStream] reads for every
 * sample type. An icon's source is its [IconSynthesizer] (run by run, phase-exact); any other [org.hapticon.core.signal.Signal]'s
 * is [SignalSource] (the signal at i / sampleRate).
 */
internal interface SampleSource {
    /** Number of samples in all. */
    val totalSamples: Long

    /** Index of the next sample [fill] makes. */
    val position: Long

    /** Writes up to [length] next samples into [destination] from [offset]; returns how many (0 at the end). */
    fun fill(destination: DoubleArray, offset: Int, length: Int): Int

    /**
     * Whether [fillFloats] has a kernel of the source's own; without one the stream narrows a double block. (A flag
     * rather than a nullable count: an `Int?` return boxes every count above 127, an allocation per block.)
     */
    val hasFloatKernel: Boolean get() = false

    /** As [fill], narrowed to floats by the source's own kernel; only when [hasFloatKernel]. The same samples either way. */
    fun fillFloats(destination: FloatArray, offset: Int, length: Int): Int =
        throw UnsupportedOperationException("this source has no float kernel")
}
