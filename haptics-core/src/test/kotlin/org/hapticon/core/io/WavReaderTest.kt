package org.hapticon.core.io

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test
import java.io.ByteArrayInputStream

class WavReaderTest {
    private fun le16(value: Int) = intArrayOf(value and 0xFF, (value shr 8) and 0xFF)
    private fun le32(value: Long) = intArrayOf(*le16((value and 0xFFFF).toInt()), *le16(((value shr 16) and 0xFFFF).toInt()))

    private fun chunk(id: String, body: ByteArray): ByteArray {
        val pad = if (body.size % 2 == 1) byteArrayOf(0) else ByteArray(0)
        return wavBytes(*asciiCodes(id), *le32(body.size.toLong())) + body + pad
    }

    private fun fmt(tag: Int, channels: Int, rate: Int, bits: Int): ByteArray {
        val align = channels * bits / 8
        return wavBytes(*le16(tag), *le16(channels), *le32(rate.toLong()), *le32(rate.toLong() * align), *le16(align), *le16(bits))
    }

    private fun wav(vararg chunks: ByteArray): ByteArray {
        val body = chunks.fold(wavBytes(*asciiCodes("WAVE"))) { acc, c -> acc + c }
        return wavBytes(*asciiCodes("RIFF"), *le32(body.size.toLong())) + body
    }

    private fun pcm(vararg values: Int): ByteArray = wavBytes(*values.flatMap { le16(it and 0xFFFF).toList() }.toIntArray())

    private fun assertRejected(data: ByteArray, message: String) {
        try {
            WavReader.read(ByteArrayInputStream(data))
            fail("accepted")
        } catch (e: WavFormatException) {
            assertEquals(message, e.message)
        }
    }

    @Test
    fun read_oddSizedChunkBeforeData_skipsItsPadByte() {
        val data = wav(chunk("fmt ", fmt(1, 1, 8000, 16)), chunk("LIST", wavBytes(1, 2, 3)), chunk("data", pcm(32767, -32767, 0)))
        assertEquals(12 + 24 + 12 + 14, data.size) // LIST: 8 + 3 + 1 pad byte
        val audio = WavReader.read(ByteArrayInputStream(data))
        assertArrayEquals(floatArrayOf(1f, -1f, 0f), audio.samples(), 0f)
        assertEquals(8000, audio.sampleRate)
        assertEquals(3.0 / 8000, audio.durationSeconds, 0.0)
    }

    @Test
    fun read_minimumPcmValue_isClampedToMinusOne() {
        val audio = WavReader.read(ByteArrayInputStream(wav(chunk("fmt ", fmt(1, 1, 8000, 16)), chunk("data", pcm(-32768, 16384)))))
        assertArrayEquals(floatArrayOf(-1f, 16384 / 32767f), audio.samples(), 0f)
    }

    @Test
    fun read_stereoPcm16_splitsChannels() {
        val data = wav(chunk("fmt ", fmt(1, 2, 44_100, 16)), chunk("data", pcm(32767, 0, -32767, 16384)))
        val audio = WavReader.read(ByteArrayInputStream(data))
        assertEquals(2, audio.channels)
        assertEquals(2, audio.frames)
        assertArrayEquals(floatArrayOf(1f, -1f), audio.channel(0), 0f)
        assertArrayEquals(floatArrayOf(0f, 16384 / 32767f), audio.channel(1), 0f)
        assertArrayEquals(floatArrayOf(1f, 0f, -1f, 16384 / 32767f), audio.samples(), 0f)
    }

    @Test(expected = IndexOutOfBoundsException::class)
    fun channel_beyondChannelCount_throws() {
        WavReader.read(ByteArrayInputStream(wav(chunk("fmt ", fmt(1, 1, 8000, 16)), chunk("data", pcm(1))))).channel(1)
    }

    @Test
    fun read_extensibleFloat_isRecognised() {
        val guidTail = wavBytes(0, 0, 0, 0, 0x10, 0, 0x80, 0, 0, 0xAA, 0, 0x38, 0x9B, 0x71)
        val extension = wavBytes(*le16(22), *le16(32), *le32(4)) + wavBytes(*le16(3)) + guidTail
        val format = fmt(0xFFFE, 1, 48_000, 32) + extension
        val samples = wavBytes(0, 0, 0, 0x3F, 0, 0, 0x80, 0xBF) // 0.5, −1
        val audio = WavReader.read(ByteArrayInputStream(wav(chunk("fmt ", format), chunk("data", samples))))
        assertEquals(WavEncoding.FLOAT32, audio.encoding)
        assertArrayEquals(floatArrayOf(0.5f, -1f), audio.samples(), 0f)
    }

    @Test
    fun read_unsupportedFormats_areRejectedClearly() {
        assertRejected(wav(chunk("fmt ", fmt(1, 1, 8000, 24)), chunk("data", ByteArray(3))), "unsupported format: tag 1 with 24 bits (reads 16-bit PCM and 32-bit float)")
        assertRejected(wav(chunk("fmt ", fmt(6, 1, 8000, 8)), chunk("data", ByteArray(1))), "unsupported format: tag 6 with 8 bits (reads 16-bit PCM and 32-bit float)")
        assertRejected(wav(chunk("fmt ", fmt(1, 3, 8000, 16)), chunk("data", ByteArray(6))), "unsupported channel count 3 (reads mono and stereo)")
    }

    @Test
    fun read_notRiffWave_isRejected() {
        assertRejected(wavBytes(*asciiCodes("RIFX"), 0, 0, 0, 0, *asciiCodes("WAVE")), "not a RIFF/WAVE file")
        assertRejected(wavBytes(*asciiCodes("RIFF"), 0, 0, 0, 0, *asciiCodes("AVI ")), "not a RIFF/WAVE file")
        assertRejected(wavBytes(*asciiCodes("RIF")), "truncated RIFF header")
    }

    @Test
    fun read_structuralErrors_areRejected() {
        assertRejected(wav(chunk("data", pcm(1))), "data chunk before the fmt chunk")
        assertRejected(wav(chunk("fmt ", fmt(1, 1, 8000, 16))), "truncated chunk header (no data chunk found)")
        assertRejected(wav(chunk("fmt ", fmt(1, 1, 8000, 16)), chunk("data", wavBytes(1, 2, 3))), "data chunk of 3 bytes is not a whole number of 2-byte frames")
        assertRejected(wav(chunk("fmt ", ByteArray(12))), "fmt chunk of 12 bytes")
        val truncated = wav(chunk("fmt ", fmt(1, 1, 8000, 16)), chunk("data", pcm(1, 2, 3)))
        assertRejected(truncated.copyOf(truncated.size - 1), "truncated data chunk")
        val skipTruncated = wav(chunk("fmt ", fmt(1, 1, 8000, 16)), wavBytes(*asciiCodes("LIST"), *le32(100), 1, 2))
        assertRejected(skipTruncated, "truncated chunk")
        val badAlign = fmt(1, 1, 8000, 16).also { it[12] = 4 }
        assertRejected(wav(chunk("fmt ", badAlign), chunk("data", pcm(1, 2))), "block align 4 does not match the format")
    }

    @Test
    fun read_moreSamplesThanTheLimit_isRejectedBeforeAllocating() {
        val data = wav(chunk("fmt ", fmt(1, 1, 8000, 16)), wavBytes(*asciiCodes("data"), *le32(0xFFFF_FFFEL)))
        try {
            WavReader.read(ByteArrayInputStream(data), maxSamples = 1000)
            fail()
        } catch (e: WavFormatException) {
            assertEquals("2147483647 samples exceed the limit of 1000", e.message)
        }
    }

    @Test
    fun stream_monoFile_readsInBlocks() {
        val values = IntArray(10_000) { (it * 7) % 65535 - 32767 }
        val data = wav(chunk("fmt ", fmt(1, 1, 8000, 16)), chunk("data", pcm(*values)))
        val stream = WavReader.stream(ByteArrayInputStream(data))
        assertEquals(8000, stream.sampleRate)
        assertEquals(10_000L, stream.totalSamples)
        val read = FloatArray(10_000)
        var total = 0
        while (true) {
            val n = stream.read(read, total, minOf(3000, read.size - total))
            if (n < 0) break
            total += n
            if (total == read.size) assertEquals(-1, stream.read(FloatArray(1)))
        }
        assertEquals(10_000, total)
        assertEquals(10_000L, stream.position)
        for (i in values.indices) assertEquals(maxOf(-1f, values[i] / 32767f), read[i], 0f)
    }

    @Test
    fun stream_stereoFile_isRejected() {
        try {
            WavReader.stream(ByteArrayInputStream(wav(chunk("fmt ", fmt(1, 2, 8000, 16)), chunk("data", pcm(1, 2)))))
            fail()
        } catch (e: WavFormatException) {
            assertEquals("a sample stream is mono; this file has 2 channels", e.message)
        }
    }
}
