package org.hapticon.core.render

/**
 * A [SampleStream] that can also yield its samples in double precision, before they are narrowed
 * to float: the values [IconRenderer.sampleAt] describes, so that differences far below float
 * resolution (such as [RenderMode.FAST] against [RenderMode.EXACT]) can be measured.
 *
 * Float and double reads draw from the same sequence and share one [position]; they may be mixed,
 * and a sample read as a double narrows to exactly the float a float read would have returned.
 */
public interface DoubleSampleStream : SampleStream {
    /**
     * Writes up to [length] next samples into [destination] from [offset] and returns how many were
     * written, or -1 once all [totalSamples] have been read. Does not allocate.
     *
     * @throws IndexOutOfBoundsException if [offset, offset + length) falls outside [destination].
     */
    public fun read(destination: DoubleArray, offset: Int = 0, length: Int = destination.size - offset): Int
}
