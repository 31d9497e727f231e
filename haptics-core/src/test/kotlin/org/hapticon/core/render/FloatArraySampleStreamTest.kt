package org.hapticon.core.render

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class FloatArraySampleStreamTest {
    @Test
    fun read_inChunks_yieldsEverySampleOnceThenMinusOne() {
        val stream = FloatArraySampleStream(floatArrayOf(0.5f, -0.25f, 1f, 0f, -1f), 48_000)
        val buffer = FloatArray(4)

        assertEquals(3, stream.read(buffer, 1, 3))
        assertArrayEquals(floatArrayOf(0f, 0.5f, -0.25f, 1f), buffer, 0f)
        assertEquals(3L, stream.position)
        assertEquals(2, stream.read(buffer, 0, 4))
        assertArrayEquals(floatArrayOf(0f, -1f), buffer.copyOf(2), 0f)
        assertEquals(-1, stream.read(buffer, 0, 4))
        assertEquals(5L, stream.totalSamples)
    }

    @Test
    fun empty_endsAtOnce_andARateOfZeroIsRefused() {
        assertEquals(-1, FloatArraySampleStream(FloatArray(0), 8_000).read(FloatArray(1), 0, 1))
        assertThrows(IllegalArgumentException::class.java) { FloatArraySampleStream(FloatArray(1), 0) }
    }
}
