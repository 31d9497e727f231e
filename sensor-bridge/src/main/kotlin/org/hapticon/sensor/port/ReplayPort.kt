package org.hapticon.sensor.port

import java.io.File
import java.io.FileInputStream
import java.io.IOException
import java.io.InputStream

/**
 * A [SerialPort] that plays back a recorded byte stream (a file of what a board sent), for the command
 * line and for tests. Reads return successive pieces of the
 * recording, sized by cycling through [readSizes] (64 by default, a USB full-speed packet), so a
 * recording can be replayed with the splits it had or any others; -1 at the end. Nothing is paced:
 * a recording replays as fast as it is read.
 *
 * Writes are counted in [bytesWritten] and discarded; [configure] is ignored. [close] closes [input].
 *
 * @throws IllegalArgumentException if [readSizes] is empty or holds a size below 1.
 */
public class ReplayPort(
    private val input: InputStream,
    private val readSizes: IntArray = intArrayOf(DEFAULT_READ_SIZE),
) : SerialPort {
    init {
        require(readSizes.isNotEmpty() && readSizes.all { it > 0 }) { "readSizes must be positive and not empty" }
    }

    /**
     * Replays [file]; see the primary constructor.
     * @throws java.io.FileNotFoundException if [file] cannot be opened.
     */
    public constructor(file: File, readSizes: IntArray = intArrayOf(DEFAULT_READ_SIZE)) : this(FileInputStream(file).buffered(), readSizes)

    private var nextSize = 0
    private var closed = false

    /** Bytes passed to [write] so far (and discarded). */
    public var bytesWritten: Long = 0
        private set

    override val isOpen: Boolean get() = !closed

    override fun configure(settings: LineSettings) {
        if (closed) throw IOException("replay port closed")
    }

    /**
     * Reads the next piece of the recording: at most the next read size, fewer at the end of the
     * recording or if the input has fewer available; -1 at the end. [timeoutMillis] is ignored.
     * @throws IOException if the port is closed or the input fails.
     */
    override fun read(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int {
        if (offset < 0 || length < 0 || offset > buffer.size - length) throw IndexOutOfBoundsException("range [$offset, $offset + $length) is outside 0..${buffer.size}")
        if (closed) throw IOException("replay port closed")
        if (length == 0) return 0
        val size = readSizes[nextSize]
        nextSize = (nextSize + 1) % readSizes.size
        var total = 0
        val wanted = minOf(length, size)
        // Fill the piece completely where the input allows, so the split is the one asked for.
        while (total < wanted) {
            val n = input.read(buffer, offset + total, wanted - total)
            if (n < 0) break
            total += n
        }
        return if (total == 0) -1 else total
    }

    /** Counts and discards the bytes. @throws IOException if the port is closed. */
    override fun write(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int) {
        if (offset < 0 || length < 0 || offset > buffer.size - length) throw IndexOutOfBoundsException("range [$offset, $offset + $length) is outside 0..${buffer.size}")
        if (closed) throw IOException("replay port closed")
        bytesWritten += length
    }

    override fun close() {
        if (closed) return
        closed = true
        input.close()
    }

    /** Defaults. */
    public companion object {
        /** Default read size: one USB full-speed bulk packet. */
        public const val DEFAULT_READ_SIZE: Int = 64
    }
}
