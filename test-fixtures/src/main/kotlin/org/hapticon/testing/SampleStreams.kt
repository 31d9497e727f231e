package org.hapticon.testing

import org.hapticon.core.render.SampleStream

/**
 * Reads everything left in this stream into one array, for assertions on short renders.
 * Fails the test (IllegalStateException) if the stream ends before its declared total.
 */
public fun SampleStream.readAllSamples(): FloatArray {
    val remaining = totalSamples - position
    check(remaining <= Int.MAX_VALUE) { "$remaining samples do not fit one array" }
    val samples = FloatArray(remaining.toInt())
    var filled = 0
    while (filled < samples.size) {
        val count = read(samples, filled, samples.size - filled)
        check(count > 0) { "stream ended after $filled of ${samples.size} samples" }
        filled += count
    }
    check(read(FloatArray(1)) == -1) { "stream yields more than its totalSamples" }
    return samples
}
