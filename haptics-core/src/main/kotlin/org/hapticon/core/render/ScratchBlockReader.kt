package org.hapticon.core.render

/**
 * Makes an [IconSynthesizer]'s samples in a fixed double scratch block (allocated once per stream),
 * for stream reads that convert them into another sample type; no allocation per read.
 */
internal class ScratchBlockReader(val synthesizer: IconSynthesizer) {
    val scratch = DoubleArray(SCRATCH_SAMPLES)

    /**
     * Makes up to [length] samples block by block, handing each to [convert] as (scratch, samples
     * converted so far, samples in this block); returns how many were made. Inline, so the converter
     * costs no allocation.
     */
    inline fun read(length: Int, convert: (scratch: DoubleArray, written: Int, made: Int) -> Unit): Int {
        var written = 0
        while (written < length) {
            val made = synthesizer.fill(scratch, 0, minOf(SCRATCH_SAMPLES, length - written))
            if (made == 0) break
            convert(scratch, written, made)
            written += made
        }
        return written
    }

    // Not private: the inline read() refers to it from callers' code.
    companion object {
        const val SCRATCH_SAMPLES = 1024
    }
}
