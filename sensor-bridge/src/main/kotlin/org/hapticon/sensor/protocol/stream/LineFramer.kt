package org.hapticon.sensor.protocol.stream

/** Receives the lines a [LineFramer] cuts. Primitive parameters, so no call boxes anything. */
internal interface LineHandler {
    /**
     * A complete line: [length] bytes of [line] from 0, without its `\n` but with any `\r` before it.
     * [frameBytes] counts the line as received, terminator included, for the statistics.
     */
    fun onLine(line: ByteArray, length: Int, frameBytes: Int)
}

/**
 * Cuts newline-terminated text into lines in one bounded buffer. A line longer than the buffer is
 * skipped up to its newline and counted as [FrameError.OVERLONG], so a stream without newlines
 * (wrong baud rate, binary data) cannot grow memory.
 */
internal class LineFramer(maxLineLength: Int, private val stats: StreamStats) {
    private val buffer = ByteArray(maxLineLength)
    private var length = 0
    private var overlong = false
    private var skipped = 0L

    /** Bytes of an unfinished line held so far. */
    val pendingBytes: Long get() = if (overlong) skipped else length.toLong()

    fun feed(bytes: ByteArray, offset: Int, count: Int, handler: LineHandler) {
        checkRange(bytes.size, offset, count)
        stats.bytes += count
        var i = offset
        val end = offset + count
        while (i < end) {
            var j = i
            while (j < end && bytes[j] != LF) j++
            val segment = j - i
            if (overlong) {
                skipped += segment
            } else if (segment > buffer.size - length) {
                overlong = true
                skipped = length.toLong() + segment
                length = 0
            } else {
                System.arraycopy(bytes, i, buffer, length, segment)
                length += segment
            }
            if (j == end) break
            if (overlong) {
                stats.rejected(FrameError.OVERLONG, saturated(skipped + 1))
                overlong = false
                skipped = 0
            } else {
                handler.onLine(buffer, length, length + 1)
            }
            length = 0
            i = j + 1
        }
    }

    /** Drops an unfinished line, counting it as truncated. */
    fun finish() {
        val pending = pendingBytes
        if (pending > 0) stats.rejected(FrameError.TRUNCATED, saturated(pending))
        length = 0
        overlong = false
        skipped = 0
    }

    private fun saturated(count: Long): Int = if (count > Int.MAX_VALUE) Int.MAX_VALUE else count.toInt()

    companion object {
        const val LF: Byte = '\n'.code.toByte()
        const val CR: Byte = '\r'.code.toByte()
    }
}
