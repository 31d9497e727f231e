package org.hapticon.core.io

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.Pcm16
import org.hapticon.core.render.PcmRenderer
import org.hapticon.core.render.SampleStream
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test
import java.io.ByteArrayInputStream
import java.io.ByteArrayOutputStream

/** A stream over [samples] that claims [totalSamples] and hands out at most [chunk] samples per read. */
internal class ArraySampleStream(
    private val samples: FloatArray,
    override val sampleRate: Int = 8000,
    override val totalSamples: Long = samples.size.toLong(),
    private val chunk: Int = 1000,
) : SampleStream {
    override var position: Long = 0

    override fun read(destination: FloatArray, offset: Int, length: Int): Int {
        if (position >= samples.size) return -1
        val count = minOf(length, chunk, samples.size - position.toInt())
        System.arraycopy(samples, position.toInt(), destination, offset, count)
        position += count
        return count
    }
}

/** Bytes from ints 0..255, for writing expected WAV files readably. */
internal fun wavBytes(vararg values: Int): ByteArray = ByteArray(values.size) { values[it].toByte() }

/** The character codes of [text]. */
internal fun asciiCodes(text: String): IntArray = text.map { it.code }.toIntArray()

class WavWriterTest {
    private fun written(stream: SampleStream, encoding: WavEncoding): ByteArray =
        ByteArrayOutputStream().also { WavWriter.write(stream, it, encoding) }.toByteArray()

    @Test
    fun write_pcm16_writesExactHeaderAndSamples() {
        val out = written(ArraySampleStream(floatArrayOf(0.5f, -1f, Float.NaN)), WavEncoding.PCM16)
        val expected = wavBytes(
            *asciiCodes("RIFF"), 42, 0, 0, 0, *asciiCodes("WAVE"),
            *asciiCodes("fmt "), 16, 0, 0, 0,
            1, 0, // PCM
            1, 0, // mono
            0x40, 0x1F, 0, 0, // 8000 Hz
            0x80, 0x3E, 0, 0, // 16000 bytes/s
            2, 0, 16, 0, // block align, bits
            *asciiCodes("data"), 6, 0, 0, 0,
            0x00, 0x40, // 0.5 → 16384 (16383.5 rounded away from zero)
            0x01, 0x80, // −1 → −32767
            0x00, 0x00, // NaN → 0
        )
        assertArrayEquals(expected, out)
    }

    @Test
    fun write_float32_writesExactHeaderFactChunkAndClippedSamples() {
        val out = written(ArraySampleStream(floatArrayOf(0.5f, -1f, Float.NaN, 1.5f)), WavEncoding.FLOAT32)
        val expected = wavBytes(
            *asciiCodes("RIFF"), 66, 0, 0, 0, *asciiCodes("WAVE"),
            *asciiCodes("fmt "), 18, 0, 0, 0,
            3, 0, // IEEE float
            1, 0, // mono
            0x40, 0x1F, 0, 0, // 8000 Hz
            0x00, 0x7D, 0, 0, // 32000 bytes/s
            4, 0, 32, 0, // block align, bits
            0, 0, // cbSize
            *asciiCodes("fact"), 4, 0, 0, 0, 4, 0, 0, 0, // 4 sample frames
            *asciiCodes("data"), 16, 0, 0, 0,
            0, 0, 0, 0x3F, // 0.5
            0, 0, 0x80, 0xBF, // −1
            0, 0, 0, 0, // NaN → 0
            0, 0, 0x80, 0x3F, // 1.5 clipped to 1
        )
        assertArrayEquals(expected, out)
    }

    @Test
    fun write_emptyStream_writesHeaderOnly() {
        val out = written(ArraySampleStream(FloatArray(0)), WavEncoding.PCM16)
        assertEquals(44, out.size)
        assertArrayEquals(wavBytes(36, 0, 0, 0), out.copyOfRange(4, 8))
        assertArrayEquals(wavBytes(0, 0, 0, 0), out.copyOfRange(40, 44))
    }

    @Test
    fun fileSize_matchesWrittenBytesAndRiffSizes() {
        for (encoding in WavEncoding.values()) {
            for (count in listOf(0, 1, 3, 4095, 4096, 4097, 10_001)) {
                val out = written(ArraySampleStream(FloatArray(count) { (it % 7 - 3) / 3f }), encoding)
                assertEquals(WavWriter.fileSize(count.toLong(), encoding), out.size.toLong())
                val riffSize = (out[4].toInt() and 0xFF) or ((out[5].toInt() and 0xFF) shl 8) or ((out[6].toInt() and 0xFF) shl 16)
                assertEquals(out.size - 8, riffSize)
            }
        }
        assertEquals(44L + 2 * 3, WavWriter.fileSize(3, WavEncoding.PCM16))
        assertEquals(58L + 4 * 3, WavWriter.fileSize(3, WavEncoding.FLOAT32))
    }

    @Test
    fun roundTrip_pcm16_matchesPcm16ConversionExactly() {
        val samples = FloatArray(10_001) { Math.sin(it * 0.01).toFloat() * 0.9f }
        val audio = WavReader.read(ByteArrayInputStream(written(ArraySampleStream(samples, 48_000), WavEncoding.PCM16)))
        assertEquals(48_000, audio.sampleRate)
        assertEquals(1, audio.channels)
        assertEquals(WavEncoding.PCM16, audio.encoding)
        val expected = FloatArray(samples.size) { Pcm16.fromSample(samples[it]) / 32767f }
        assertArrayEquals(expected, audio.samples(), 0f)
    }

    @Test
    fun roundTrip_float32_isExact() {
        val samples = FloatArray(5000) { Math.sin(it * 0.37).toFloat() }
        val audio = WavReader.read(ByteArrayInputStream(written(ArraySampleStream(samples, 44_100), WavEncoding.FLOAT32)))
        assertEquals(WavEncoding.FLOAT32, audio.encoding)
        assertArrayEquals(samples, audio.samples(), 0f)
    }

    @Test
    fun write_pcmStream_matchesTheRenderedPcm() {
        val renderer = PcmRenderer(HapticIcon.KNOCK, 8000)
        val out = ByteArrayOutputStream().also { WavWriter.write(renderer.stream(), it) }.toByteArray()
        assertEquals(WavWriter.fileSize(renderer.sampleCount, WavEncoding.PCM16), out.size.toLong())
        val audio = WavReader.read(ByteArrayInputStream(out))
        val expected = renderer.toShortArray()
        assertEquals(expected.size, audio.frames)
        val actual = audio.samples()
        for (i in expected.indices) assertEquals(expected[i] / 32767f, actual[i], 0f)
    }

    @Test
    fun write_partlyReadStream_isRejected() {
        val stream = ArraySampleStream(FloatArray(10))
        stream.read(FloatArray(2))
        try {
            WavWriter.write(stream, ByteArrayOutputStream())
            fail()
        } catch (e: IllegalArgumentException) {
            assertEquals("the stream has already been read up to sample 2", e.message)
        }
    }

    @Test
    fun write_streamEndingEarly_failsInsteadOfWritingAWrongFile() {
        try {
            WavWriter.write(ArraySampleStream(FloatArray(5000), totalSamples = 6000), ByteArrayOutputStream())
            fail()
        } catch (e: IllegalStateException) {
            assertEquals("the stream ended after 5000 of its 6000 samples", e.message)
        }
    }

    @Test
    fun write_streamStalling_failsInsteadOfHanging() {
        val stalled = object : SampleStream {
            override val sampleRate = 8000
            override val totalSamples = 10L
            override val position = 0L
            override fun read(destination: FloatArray, offset: Int, length: Int) = 0
        }
        try {
            WavWriter.write(stalled, ByteArrayOutputStream())
            fail()
        } catch (e: IllegalStateException) {
            assertEquals("the stream ended after 0 of its 10 samples", e.message)
        }
    }

    @Test
    fun write_streamTooLongForRiff_isRejectedBeforeWriting() {
        val out = ByteArrayOutputStream()
        try {
            WavWriter.write(ArraySampleStream(FloatArray(0), totalSamples = 3_000_000_000L), out)
            fail()
        } catch (e: IllegalArgumentException) {
            assertEquals("3000000000 samples do not fit a WAV file", e.message)
        }
        assertEquals(0, out.size())
    }

    @Test
    fun write_riffSizeLimit_isExactlyFourGigabytes() {
        // RIFF size = 36 + 2n must fit 32 bits: n = 2147483629 is the longest PCM16 stream.
        val longest = (0xFFFF_FFFFL - 36) / 2
        val out = ByteArrayOutputStream()
        try {
            WavWriter.write(ArraySampleStream(FloatArray(0), totalSamples = longest), out)
            fail()
        } catch (e: IllegalStateException) {
            // Accepted: the header went out, then the (empty) stream ran dry.
            assertEquals(44, out.size())
            assertArrayEquals(wavBytes(0xFE, 0xFF, 0xFF, 0xFF), out.toByteArray().copyOfRange(4, 8))
        }
        try {
            WavWriter.write(ArraySampleStream(FloatArray(0), totalSamples = longest + 1), ByteArrayOutputStream())
            fail()
        } catch (e: IllegalArgumentException) {
            assertEquals("${longest + 1} samples do not fit a WAV file", e.message)
        }
    }
}
