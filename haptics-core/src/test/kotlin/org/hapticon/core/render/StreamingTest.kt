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
    fun readDoubles_bothModesAndModels_narrowToTheFloatReadExactly() {
        for (mode in RenderMode.values()) for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(HapticIcon.HIT, 48_000, model, mode)
            val floats = readAll(renderer.stream(), 4096)
            val stream = renderer.stream()
            val block = DoubleArray(483)
            var index = 0
            while (true) {
                // Offset 3 exercises the offset argument.
                val n = stream.read(block, 3, 480)
                if (n < 0) break
                assertEquals(index + n.toLong(), stream.position)
                for (j in 0 until n) assertEquals("$mode $model ${index + j}", floats[index + j], block[3 + j].toFloat(), 0f)
                index += n
            }
            assertEquals(73_920, index)
        }
    }

    @Test
    fun readDoubles_exactMode_equalsSampleAtBitForBit() {
        for (model in EnvelopeModel.values()) {
            assertEquals(24_696L, RenderAssertions.streamEqualsSampleAt(IconRenderer(HapticIcon.KNOCK, 44_100, model), "$model"))
        }
    }

    @Test
    fun read_floatsAndDoublesMixed_continueOneSequence() {
        val renderer = IconRenderer(HapticIcon.HIT, 44_100, mode = RenderMode.FAST)
        val reference = readAll(renderer.stream(), 4096)
        val stream = renderer.stream()
        val floats = FloatArray(700)
        val doubles = DoubleArray(1300)
        assertEquals(700, stream.read(floats))
        assertEquals(1300, stream.read(doubles))
        assertEquals(2_000L, stream.position)
        assertEquals(reference[699], floats[699], 0f)
        assertEquals(reference[700], doubles[0].toFloat(), 0f)
        assertEquals(reference[1999], doubles[1299].toFloat(), 0f)
        assertEquals(700, stream.read(floats))
        assertEquals(reference[2000], floats[0], 0f)
    }

    @Test
    fun readDoubles_atEnd_returnsMinusOne() {
        val stream = IconRenderer(HapticIcon.KNOCK, 48_000).stream()
        val block = DoubleArray(20_000)
        assertEquals(20_000, stream.read(block))
        assertEquals(6_880, stream.read(block))
        assertEquals(-1, stream.read(block))
        assertEquals(-1, stream.read(block, 0, 0))
        assertEquals(26_880L, stream.position)
    }

    @Test
    fun readDoubles_zeroLengthBeforeEnd_returnsZero() {
        val stream = IconRenderer(HapticIcon.KNOCK, 48_000).stream()
        assertEquals(0, stream.read(DoubleArray(4), 2, 0))
        assertEquals(0L, stream.position)
    }

    @Test(expected = IndexOutOfBoundsException::class)
    fun readDoubles_rangeOutsideArray_throws() {
        IconRenderer(HapticIcon.KNOCK, 48_000).stream().read(DoubleArray(4), 2, 3)
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
