package org.hapticon.core.render

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows

/** Assertions the render tests share. */
internal object RenderAssertions {
    /**
     * Reads [renderer]'s stream to its end in blocks of 1,000 and asserts each sample equals [IconRenderer.sampleAt] at
     * its index to the bit ([label] names the case); returns how many samples the stream gave.
     */
    fun streamEqualsSampleAt(renderer: IconRenderer, label: String): Long {
        val stream = renderer.stream()
        val block = DoubleArray(1000)
        var index = 0L
        while (true) {
            val n = stream.read(block)
            if (n < 0) break
            for (j in 0 until n) assertEquals("$label ${index + j}", renderer.sampleAt(index + j), block[j], 0.0)
            index += n
        }
        return index
    }

    /** [call] throws an [IllegalArgumentException] whose message is [message]. */
    fun assertRejected(message: String, call: () -> Unit) {
        assertEquals(message, assertThrows(IllegalArgumentException::class.java) { call() }.message)
    }
}
