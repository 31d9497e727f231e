package org.hapticon.companion.bench

import org.hapticon.sensor.protocol.stream.StreamDecoder
import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.protocol.lucid.LucidGloveDecoder

/**
 * Measures decoding speed on one core, for `hapticon bench`: each protocol decodes a synthetic
 * buffer of realistic frames (5-channel CSV lines, 5-channel framed samples, LucidGloves lines with
 * splay) fed in reads of [DEFAULT_READ_SIZE] bytes, after warm-up runs for the JIT. Also reports
 * the bytes allocated per frame on the decoding thread, which should be 0.
 */
public object ProtocolBenchmark {
    /** Default size of each synthetic buffer. */
    public const val DEFAULT_BUFFER_BYTES: Int = 16 shl 20

    /** Default bytes per `feed` call, like one [org.hapticon.sensor.port.SensorReader] read. */
    public const val DEFAULT_READ_SIZE: Int = 4096

    /** One protocol's figures. */
    public class Result(
        /** `csv`, `framed` or `lucidgloves`. */
        public val name: String,
        /** Bytes decoded per run. */
        public val bytes: Long,
        /** Frames delivered per run. */
        public val frames: Long,
        /** Median decoding speed over the measured runs, in MB/s (10^6 bytes per second). */
        public val megabytesPerSecond: Double,
        /** Median frames per second. */
        public val framesPerSecond: Double,
        /** Bytes allocated on the decoding thread per frame during one run; NaN where the JVM cannot tell (Android). */
        public val bytesAllocatedPerFrame: Double,
    ) {
        /** One line: name, MB/s, frames/s, allocation. */
        override fun toString(): String =
            "%s: %.1f MB/s, %.0f frames/s, %.2f bytes allocated per frame".format(name, megabytesPerSecond, framesPerSecond, bytesAllocatedPerFrame)
    }

    /**
     * Runs the benchmark: for each protocol, [warmupRuns] unmeasured runs and [runs] measured ones
     * over a buffer of about [bufferBytes], fed [readSize] bytes at a time. Takes about a second per
     * protocol at the defaults.
     * @throws IllegalArgumentException if [bufferBytes] is below 4096, [runs] below 1,
     *   [warmupRuns] negative or [readSize] below 1.
     */
    public fun run(
        bufferBytes: Int = DEFAULT_BUFFER_BYTES,
        runs: Int = 5,
        warmupRuns: Int = 3,
        readSize: Int = DEFAULT_READ_SIZE,
    ): List<Result> {
        require(bufferBytes >= 4096) { "bufferBytes must be at least 4096, was $bufferBytes" }
        require(runs >= 1) { "runs must be at least 1, was $runs" }
        require(warmupRuns >= 0) { "warmupRuns must not be negative, was $warmupRuns" }
        require(readSize >= 1) { "readSize must be at least 1, was $readSize" }
        val sink = Sink()
        return listOf(
            measure("csv", csvBuffer(bufferBytes), { CsvDecoder(sink, fieldCount = 5) }, runs, warmupRuns, readSize),
            measure("framed", framedBuffer(bufferBytes), { FramedDecoder(sink) }, runs, warmupRuns, readSize),
            measure("lucidgloves", lucidBuffer(bufferBytes), { LucidGloveDecoder(sink) }, runs, warmupRuns, readSize),
        )
    }

    private fun measure(name: String, data: ByteArray, decoder: () -> StreamDecoder, runs: Int, warmupRuns: Int, readSize: Int): Result {
        repeat(warmupRuns) { decodeAll(decoder(), data, readSize) }
        val nanos = LongArray(runs)
        var frames = 0L
        var allocated = Double.NaN
        for (r in 0 until runs) {
            val d = decoder()
            val allocatedBefore = ThreadAllocation.bytes()
            val start = System.nanoTime()
            decodeAll(d, data, readSize)
            nanos[r] = System.nanoTime() - start
            val allocatedAfter = ThreadAllocation.bytes()
            frames = d.stats.frames
            // The least over the runs: a per-frame allocation shows in every run, a one-off (JIT, class
            // loading) in one only.
            if (allocatedBefore >= 0 && allocatedAfter >= 0) {
                val bytes = (allocatedAfter - allocatedBefore).toDouble()
                allocated = if (allocated.isNaN()) bytes else minOf(allocated, bytes)
            }
        }
        nanos.sort()
        val median = nanos[runs / 2].coerceAtLeast(1)
        val seconds = median / 1e9
        return Result(name, data.size.toLong(), frames, data.size / seconds / 1e6, frames / seconds, allocated / frames.coerceAtLeast(1))
    }

    private fun decodeAll(decoder: StreamDecoder, data: ByteArray, readSize: Int) {
        var offset = 0
        while (offset < data.size) {
            val n = minOf(readSize, data.size - offset)
            decoder.feed(data, offset, n)
            offset += n
        }
        decoder.finish()
    }

    private fun csvBuffer(size: Int): ByteArray {
        val text = StringBuilder(size + 64)
        var k = 0
        while (text.length < size) {
            for (c in 0 until 5) {
                if (c > 0) text.append(',')
                text.append(adc(k, c))
            }
            text.append("\r\n")
            k++
        }
        return text.toString().toByteArray(Charsets.US_ASCII)
    }

    private fun lucidBuffer(size: Int): ByteArray {
        val text = StringBuilder(size + 128)
        var k = 0
        while (text.length < size) {
            for (f in 0 until 5) text.append('A' + f).append(adc(k, f))
            text.append('F').append(adc(k, 5)).append('G').append(adc(k, 6)).append('P').append(adc(k, 7))
            if (k % 3 == 0) text.append("IL")
            for (f in 0 until 5) text.append('(').append('A' + f).append("B)").append(adc(k, 8 + f))
            text.append('\n')
            k++
        }
        return text.toString().toByteArray(Charsets.US_ASCII)
    }

    private fun framedBuffer(size: Int): ByteArray {
        val encoder = FramedEncoder()
        val frame = ByteArray(org.hapticon.sensor.protocol.framed.FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val out = java.io.ByteArrayOutputStream(size + frame.size)
        val values = IntArray(5)
        var k = 0
        while (out.size() < size) {
            for (c in values.indices) values[c] = adc(k, c)
            out.write(frame, 0, encoder.sample(1000L * k, values, frame))
            k++
        }
        return out.toByteArray()
    }

    /** A plausible 12-bit reading that varies by frame and channel. */
    private fun adc(frame: Int, channel: Int): Int = (frame * 37 + channel * 911 + (frame * channel) % 97) and 0xFFF

    /** Consumes every frame so the JIT cannot drop the decoding. */
    private class Sink : CsvDecoder.Listener, FramedDecoder.Listener, LucidGloveDecoder.Listener {
        var checksum = 0L

        override fun onSample(sample: org.hapticon.sensor.protocol.csv.CsvSample) {
            checksum += sample.values[0].toLong()
        }

        override fun onSample(frame: SampleFrame) {
            checksum += frame.values[0]
        }

        override fun onFrame(frame: org.hapticon.sensor.protocol.lucid.LucidGloveFrame) {
            checksum += frame.curl[0]
        }
    }
}

/** Bytes allocated so far by the current thread, or -1 where the JVM does not say (Android has no java.lang.management). */
private object ThreadAllocation {
    private val bean: com.sun.management.ThreadMXBean? = try {
        (java.lang.management.ManagementFactory.getThreadMXBean() as? com.sun.management.ThreadMXBean)
            ?.takeIf { it.isThreadAllocatedMemorySupported }
            ?.also { it.isThreadAllocatedMemoryEnabled = true }
    } catch (e: LinkageError) {
        null
    } catch (e: UnsupportedOperationException) {
        null
    } catch (e: SecurityException) {
        null
    }

    @Suppress("DEPRECATION") // Thread.getId(): threadId() needs Java 19.
    fun bytes(): Long = bean?.getThreadAllocatedBytes(Thread.currentThread().id) ?: -1
}
