package org.hapticon.core.render

/** A finite mono PCM16 signal read block by block, like [SampleStream] but with 16-bit samples. */
public interface PcmStream {
    /** Samples per second. */
    public val sampleRate: Int

    /** Number of samples this stream yields in all. */
    public val totalSamples: Long

    /** Index of the next sample [read] will return. */
    public val position: Long

    /**
     * Writes up to [length] next samples into [destination] from [offset] and returns how many were
     * written, or -1 once all [totalSamples] have been read. Does not allocate.
     *
     * @throws IndexOutOfBoundsException if [offset, offset + length) falls outside [destination].
     */
    public fun read(destination: ShortArray, offset: Int = 0, length: Int = destination.size - offset): Int
}
