package org.hapticon.core.render

/**
 * A finite mono signal read block by block, so that no render has to hold the whole buffer.
 * Samples are in [-1, 1] at [sampleRate]; sample i is at time i / sampleRate.
 */
public interface SampleStream {
    /** Samples per second. */
    public val sampleRate: Int

    /** Number of samples this stream yields in all: round(duration · sampleRate). */
    public val totalSamples: Long

    /** Index of the next sample [read] will return. */
    public val position: Long

    /**
     * Writes up to [length] next samples into [destination] from [offset] and returns how many were
     * written, or -1 once all [totalSamples] have been read. Does not allocate.
     */
    public fun read(destination: FloatArray, offset: Int = 0, length: Int = destination.size - offset): Int
}
