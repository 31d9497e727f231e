package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Test

class StreamingTest {
    private fun readAll(stream: SampleStream, blockSize: Int): FloatArray {
        val out = FloatArray(stream.totalSamples.toInt())
        val block = FloatArray(blockSize + 3)
        var filled = 0
        while (true) {
            val before = stream.position
            // Offset 3 exercises the offset argument.
            val n = stream.read(block, 3, blockSize)
            if (n < 0) break
            assertEquals(before + n, stream.position)
            System.arraycopy(block, 3, out, filled, n)
            filled += n
        }
        assertEquals(out.size, filled)
        return out
    }

    @Test
    fun read_blockSizes1And7And480And4096_giveIdenticalSamplesInBothModes() {
        for (mode in RenderMode.values()) for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(HapticIcon.HIT, 48_000, model, mode)
            val reference = readAll(renderer.stream(), 4096)
            assertEquals(73_920, reference.size)
            for (size in listOf(1, 7, 480)) {
                assertArrayEquals("$mode $model block $size", reference, readAll(renderer.stream(), size), 0f)
            }
        }
    }

    @Test
    fun read_exactMode_equalsSampleAtNarrowedToFloat() {
        for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(HapticIcon.KNOCK, 44_100, model)
            val samples = readAll(renderer.stream(), 480)
            for (i in samples.indices) assertEquals("$model $i", renderer.sampleAt(i.toLong()).toFloat(), samples[i], 0f)
        }
    }

    @Test
    fun read_atEnd_returnsMinusOneAndPositionStaysAtTotal() {
        val stream = IconRenderer(HapticIcon.KNOCK, 48_000).stream()
        assertEquals(26_880L, stream.totalSamples)
        assertEquals(0L, stream.position)
        val block = FloatArray(10_000)
        assertEquals(10_000, stream.read(block))
        assertEquals(10_000L, stream.position)
        assertEquals(10_000, stream.read(block))
        assertEquals(6_880, stream.read(block))
        assertEquals(26_880L, stream.position)
        assertEquals(-1, stream.read(block))
        assertEquals(-1, stream.read(block, 0, 0))
        assertEquals(26_880L, stream.position)
    }

    @Test
    fun read_zeroLengthBeforeEnd_returnsZero() {
        val stream = IconRenderer(HapticIcon.KNOCK, 48_000).stream()
        assertEquals(0, stream.read(FloatArray(4), 2, 0))
        assertEquals(0L, stream.position)
    }

    @Test(expected = IndexOutOfBoundsException::class)
    fun read_rangeOutsideArray_throws() {
        IconRenderer(HapticIcon.KNOCK, 48_000).stream().read(FloatArray(4), 2, 3)
    }

    @Test
    fun stream_eachCall_startsAfreshAtSampleZero() {
        val renderer = IconRenderer(HapticIcon.HUG, 48_000, mode = RenderMode.FAST)
        val first = renderer.stream()
        first.read(FloatArray(1000))
        val second = renderer.stream()
        assertEquals(0L, second.position)
        val block = FloatArray(2)
        second.read(block)
        assertEquals(renderer.sampleAt(1).toFloat(), block[1], 1e-6f)
    }
}
