package org.hapticon.core.io

import org.hapticon.core.render.Pcm16
import org.hapticon.core.render.SampleStream
import java.io.InputStream

/**
 * Reads mono or stereo WAV files holding 16-bit PCM or 32-bit float samples, plain (tags 1 and 3) or
 * WAVE_FORMAT_EXTENSIBLE with the matching sub-format.
 *
 * Chunks other than `fmt ` and `data` are skipped, including their pad byte when their size is odd.
 * PCM16 values are divided by 32767 (the inverse of [WavWriter]'s scale) and −32768 is clamped to −1, so
 * samples are in [-1, 1]; float samples are returned as stored. Anything else fails with a clear
 * [WavFormatException]. Nothing is closed.
 */
public object WavReader {
    /** Default cap on the samples [read] accepts: 16 Mi (64 MiB of floats, about 3 minutes of 48 kHz stereo). */
    public const val DEFAULT_MAX_SAMPLES: Int = 1 shl 24

    private const val MAX_FMT_SIZE = 1024
    private const val BLOCK_FRAMES = 4096

    /**
     * Reads a whole WAV file from [input] (up to the end of its `data` chunk).
     *
     * Throws [WavFormatException] when the data is not a RIFF/WAVE file, is truncated, holds a format other
     * than 16-bit PCM or 32-bit float with 1 or 2 channels, or has more than [maxSamples] samples (all
     * channels counted); any other [java.io.IOException] from [input].
     */
    public fun read(input: InputStream, maxSamples: Int = DEFAULT_MAX_SAMPLES): WavAudio {
        val format = readHeader(input)
        val sampleCount = format.frames * format.channels
        if (sampleCount > maxSamples) throw WavFormatException("$sampleCount samples exceed the limit of $maxSamples")
        val samples = FloatArray(sampleCount.toInt())
        val bytes = ByteArray(BLOCK_FRAMES * format.encoding.bytesPerSample)
        var done = 0
        while (done < samples.size) {
            val count = minOf(BLOCK_FRAMES, samples.size - done)
            readFully(input, bytes, count * format.encoding.bytesPerSample, "data chunk")
            decode(bytes, format.encoding, samples, done, count)
            done += count
        }
        return WavAudio(format.sampleRate, format.channels, format.encoding, samples)
    }

    /**
     * Opens the mono WAV file in [input] as a [SampleStream] that reads its samples on demand. Its `read`
     * throws [WavFormatException] when the data chunk turns out to be truncated.
     *
     * Throws [WavFormatException] as [read] does, and for a stereo file (a [SampleStream] is mono).
     */
    public fun stream(input: InputStream): SampleStream {
        val format = readHeader(input)
        if (format.channels != 1) throw WavFormatException("a sample stream is mono; this file has ${format.channels} channels")
        return WavSampleStream(input, format)
    }

    private class Format(val sampleRate: Int, val channels: Int, val encoding: WavEncoding, val frames: Long)

    /** Reads up to the start of the sample data. */
    private fun readHeader(input: InputStream): Format {
        val riff = ByteArray(12)
        readFully(input, riff, 12, "RIFF header")
        if (ascii(riff, 0) != "RIFF" || ascii(riff, 8) != "WAVE") throw WavFormatException("not a RIFF/WAVE file")
        var format: Format? = null
        val chunkHeader = ByteArray(8)
        while (true) {
            readFully(input, chunkHeader, 8, "chunk header (no data chunk found)")
            val id = ascii(chunkHeader, 0)
            val size = u32(chunkHeader, 4)
            when (id) {
                "fmt " -> format = readFormat(input, size)
                "data" -> {
                    val found = format ?: throw WavFormatException("data chunk before the fmt chunk")
                    val blockAlign = found.channels * found.encoding.bytesPerSample
                    if (size % blockAlign != 0L) {
                        throw WavFormatException("data chunk of $size bytes is not a whole number of $blockAlign-byte frames")
                    }
                    return Format(found.sampleRate, found.channels, found.encoding, size / blockAlign)
                }
                // RIFF pads odd-sized chunk data to an even length; the pad byte is not counted in the size.
                else -> skipFully(input, size + (size and 1L))
            }
        }
    }

    private fun readFormat(input: InputStream, size: Long): Format {
        if (size < 16 || size > MAX_FMT_SIZE) throw WavFormatException("fmt chunk of $size bytes")
        val fmt = ByteArray(size.toInt() + (size.toInt() and 1))
        readFully(input, fmt, fmt.size, "fmt chunk")
        var tag = u16(fmt, 0)
        val channels = u16(fmt, 2)
        val sampleRate = u32(fmt, 4)
        val blockAlign = u16(fmt, 12)
        val bits = u16(fmt, 14)
        if (tag == EXTENSIBLE) {
            if (size < 40 || u16(fmt, 16) < 22) throw WavFormatException("WAVE_FORMAT_EXTENSIBLE fmt chunk too short")
            if (!(0 until 14).all { fmt[26 + it] == GUID_TAIL[it] }) throw WavFormatException("unknown WAVE_FORMAT_EXTENSIBLE sub-format")
            tag = u16(fmt, 24)
        }
        val encoding = when {
            tag == 1 && bits == 16 -> WavEncoding.PCM16
            tag == 3 && bits == 32 -> WavEncoding.FLOAT32
            else -> throw WavFormatException("unsupported format: tag $tag with $bits bits (reads 16-bit PCM and 32-bit float)")
        }
        if (channels !in 1..2) throw WavFormatException("unsupported channel count $channels (reads mono and stereo)")
        if (sampleRate !in 1L..Int.MAX_VALUE) throw WavFormatException("invalid sample rate $sampleRate")
        if (blockAlign != channels * encoding.bytesPerSample) throw WavFormatException("block align $blockAlign does not match the format")
        return Format(sampleRate.toInt(), channels, encoding, frames = 0)
    }

    /** Decodes [count] little-endian samples from [bytes] into [destination] from [offset]. */
    private fun decode(bytes: ByteArray, encoding: WavEncoding, destination: FloatArray, offset: Int, count: Int) {
        for (i in 0 until count) {
            destination[offset + i] = when (encoding) {
                WavEncoding.PCM16 -> maxOf(-1f, ((bytes[2 * i].toInt() and 0xFF) or (bytes[2 * i + 1].toInt() shl 8)).toFloat() / Pcm16.FULL_SCALE)
                WavEncoding.FLOAT32 -> Float.fromBits(u32(bytes, 4 * i).toInt())
            }
        }
    }

    /** Mono samples read from [input] block by block on demand. */
    private class WavSampleStream(private val input: InputStream, format: Format) : SampleStream {
        private val encoding = format.encoding
        private val bytes = ByteArray(BLOCK_FRAMES * encoding.bytesPerSample)
        override val sampleRate: Int = format.sampleRate
        override val totalSamples: Long = format.frames
        override var position: Long = 0
            private set

        override fun read(destination: FloatArray, offset: Int, length: Int): Int {
            if (offset < 0 || length < 0 || offset > destination.size - length) {
                throw IndexOutOfBoundsException("offset $offset and length $length do not fit an array of ${destination.size}")
            }
            if (position >= totalSamples) return -1
            val count = minOf(length.toLong(), totalSamples - position, BLOCK_FRAMES.toLong()).toInt()
            readFully(input, bytes, count * encoding.bytesPerSample, "data chunk")
            decode(bytes, encoding, destination, offset, count)
            position += count
            return count
        }
    }

    private const val EXTENSIBLE = 0xFFFE

    /** Bytes 2..15 of every KSDATAFORMAT_SUBTYPE GUID (PCM, IEEE_FLOAT, …); bytes 0..1 hold the format tag. */
    private val GUID_TAIL = byteArrayOf(0, 0, 0, 0, 0x10, 0, 0x80.toByte(), 0, 0, 0xAA.toByte(), 0, 0x38, 0x9B.toByte(), 0x71)

    private fun readFully(input: InputStream, buffer: ByteArray, length: Int, what: String) {
        var done = 0
        while (done < length) {
            val count = input.read(buffer, done, length - done)
            if (count < 0) throw WavFormatException("truncated $what")
            done += count
        }
    }

    private fun skipFully(input: InputStream, length: Long) {
        var remaining = length
        while (remaining > 0) {
            val skipped = input.skip(remaining)
            if (skipped > 0) {
                remaining -= skipped
            } else {
                // skip() may return 0 without being at the end; a read tells the two apart.
                if (input.read() < 0) throw WavFormatException("truncated chunk")
                remaining--
            }
        }
    }

    private fun ascii(bytes: ByteArray, at: Int): String = String(CharArray(4) { (bytes[at + it].toInt() and 0xFF).toChar() })

    private fun u16(bytes: ByteArray, at: Int): Int = (bytes[at].toInt() and 0xFF) or ((bytes[at + 1].toInt() and 0xFF) shl 8)

    private fun u32(bytes: ByteArray, at: Int): Long = (u16(bytes, at) or (u16(bytes, at + 2) shl 16)).toLong() and 0xFFFF_FFFFL
}
