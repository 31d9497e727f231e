package org.hapticon.core.io

import org.hapticon.core.render.Pcm16
import org.hapticon.core.render.PcmStream
import org.hapticon.core.render.SampleStream
import java.io.OutputStream

/**
 * Writes mono streams as WAV files, block by block, without holding the whole signal.
 *
 * The header is written first with exact sizes, because a stream knows its total sample count up front.
 * Layouts (all little-endian):
 * - [WavEncoding.PCM16]: `RIFF`, `WAVE`, a 16-byte `fmt ` chunk (tag 1), then `data`: a 44-byte header.
 * - [WavEncoding.FLOAT32]: `RIFF`, `WAVE`, an 18-byte `fmt ` chunk (tag 3, cbSize 0), a `fact` chunk with
 *   the sample count, then `data`: a 58-byte header. The spec requires the cbSize field and the `fact`
 *   chunk for every non-PCM format. Plain tag 3 rather than WAVE_FORMAT_EXTENSIBLE because extensible is
 *   only needed for more than two channels or unusual bit depths, and tag 3 is what libsndfile, sox,
 *   SciPy and Audacity write and read for mono float.
 *
 * Every data chunk here has an even size (2 or 4 bytes per sample), so no RIFF pad byte is ever needed.
 * Samples follow the PCM16 safety rule in both encodings: clipped to [-1, 1], NaN written as 0.
 * The writer does not close or flush [OutputStream]s.
 */
public object WavWriter {
    private const val BLOCK_SAMPLES = 4096
    private const val PCM_FMT_SIZE = 16
    private const val FLOAT_FMT_SIZE = 18
    private const val MAX_RIFF_SIZE = 0xFFFF_FFFFL

    /**
     * The exact number of bytes [write] produces for [totalSamples] samples in [encoding].
     *
     * Throws [IllegalArgumentException] when [totalSamples] is negative.
     */
    public fun fileSize(totalSamples: Long, encoding: WavEncoding): Long {
        require(totalSamples >= 0) { "totalSamples must be >= 0, was $totalSamples" }
        return headerSize(encoding) + totalSamples * encoding.bytesPerSample
    }

    /**
     * Writes all of [stream] (which must be unread) to [out] as a mono WAV file in [encoding].
     *
     * Throws [IllegalArgumentException] when the stream has already been read from or is too long for a
     * RIFF file (4 GiB), [IllegalStateException] when the stream ends before its [SampleStream.totalSamples]
     * or stops making progress (the output is then incomplete), and any [java.io.IOException] from [out].
     */
    public fun write(stream: SampleStream, out: OutputStream, encoding: WavEncoding = WavEncoding.PCM16) {
        require(stream.position == 0L) { "the stream has already been read up to sample ${stream.position}" }
        writeHeader(out, stream.sampleRate, stream.totalSamples, encoding)
        val samples = FloatArray(BLOCK_SAMPLES)
        val shorts = ShortArray(BLOCK_SAMPLES)
        val bytes = ByteArray(BLOCK_SAMPLES * encoding.bytesPerSample)
        var remaining = stream.totalSamples
        while (remaining > 0) {
            val count = stream.read(samples, 0, minOf(BLOCK_SAMPLES.toLong(), remaining).toInt())
            checkProgress(count, remaining, stream.totalSamples)
            when (encoding) {
                WavEncoding.PCM16 -> {
                    Pcm16.convert(samples, shorts, length = count)
                    for (i in 0 until count) putShort(bytes, i * 2, shorts[i].toInt())
                }
                WavEncoding.FLOAT32 -> for (i in 0 until count) {
                    putInt(bytes, i * 4, java.lang.Float.floatToRawIntBits(safeFloat(samples[i])))
                }
            }
            out.write(bytes, 0, count * encoding.bytesPerSample)
            remaining -= count
        }
    }

    /**
     * Writes all of [stream] (which must be unread), already converted to PCM16, to [out] as a mono
     * 16-bit WAV file.
     *
     * Throws as the [SampleStream] overload does.
     */
    public fun write(stream: PcmStream, out: OutputStream) {
        require(stream.position == 0L) { "the stream has already been read up to sample ${stream.position}" }
        writeHeader(out, stream.sampleRate, stream.totalSamples, WavEncoding.PCM16)
        val shorts = ShortArray(BLOCK_SAMPLES)
        val bytes = ByteArray(BLOCK_SAMPLES * 2)
        var remaining = stream.totalSamples
        while (remaining > 0) {
            val count = stream.read(shorts, 0, minOf(BLOCK_SAMPLES.toLong(), remaining).toInt())
            checkProgress(count, remaining, stream.totalSamples)
            for (i in 0 until count) putShort(bytes, i * 2, shorts[i].toInt())
            out.write(bytes, 0, count * 2)
            remaining -= count
        }
    }

    private fun headerSize(encoding: WavEncoding): Int = when (encoding) {
        WavEncoding.PCM16 -> 12 + (8 + PCM_FMT_SIZE) + 8
        WavEncoding.FLOAT32 -> 12 + (8 + FLOAT_FMT_SIZE) + (8 + 4) + 8
    }

    /** A read must make progress: a stream that ends early or returns 0 forever would leave a wrong header or hang. */
    private fun checkProgress(count: Int, remaining: Long, total: Long) {
        check(count > 0) { "the stream ended after ${total - remaining} of its $total samples" }
    }

    private fun writeHeader(out: OutputStream, sampleRate: Int, totalSamples: Long, encoding: WavEncoding) {
        require(sampleRate > 0) { "sampleRate must be > 0, was $sampleRate" }
        val dataSize = totalSamples * encoding.bytesPerSample
        val riffSize = fileSize(totalSamples, encoding) - 8
        require(riffSize <= MAX_RIFF_SIZE) { "$totalSamples samples do not fit a WAV file" }
        val header = ByteArray(headerSize(encoding))
        var at = 0
        fun ascii(text: String) {
            for (c in text) header[at++] = c.code.toByte()
        }
        fun u16(value: Int) {
            putShort(header, at, value)
            at += 2
        }
        fun u32(value: Long) {
            putInt(header, at, value.toInt())
            at += 4
        }
        ascii("RIFF")
        u32(riffSize)
        ascii("WAVE")
        ascii("fmt ")
        u32(if (encoding == WavEncoding.PCM16) PCM_FMT_SIZE.toLong() else FLOAT_FMT_SIZE.toLong())
        u16(if (encoding == WavEncoding.PCM16) 1 else 3) // format tag
        u16(1) // channels
        u32(sampleRate.toLong())
        u32(sampleRate.toLong() * encoding.bytesPerSample) // bytes per second
        u16(encoding.bytesPerSample) // block align
        u16(encoding.bytesPerSample * 8) // bits per sample
        if (encoding == WavEncoding.FLOAT32) {
            u16(0) // cbSize: no extension
            ascii("fact")
            u32(4)
            u32(totalSamples) // sample frames
        }
        ascii("data")
        u32(dataSize)
        out.write(header)
    }

    private fun safeFloat(value: Float): Float = if (value.isNaN()) 0f else value.coerceIn(-1f, 1f)

    private fun putShort(bytes: ByteArray, at: Int, value: Int) {
        bytes[at] = value.toByte()
        bytes[at + 1] = (value shr 8).toByte()
    }

    private fun putInt(bytes: ByteArray, at: Int, value: Int) {
        bytes[at] = value.toByte()
        bytes[at + 1] = (value shr 8).toByte()
        bytes[at + 2] = (value shr 16).toByte()
        bytes[at + 3] = (value shr 24).toByte()
    }
}
