package org.hapticon.sensor.protocol.csv

import org.hapticon.sensor.protocol.stream.Decimal
import org.hapticon.sensor.protocol.stream.FrameError
import org.hapticon.sensor.protocol.stream.LineFramer
import org.hapticon.sensor.protocol.stream.LineHandler
import org.hapticon.sensor.protocol.stream.StreamDecoder
import org.hapticon.sensor.protocol.stream.StreamStats

/**
 * Decodes the lines of numbers Arduino sketches print (`512,498,1023\n`, integers or decimals,
 * `\n` or `\r\n`), delivering each data line to [listener] as a reused [CsvSample].
 *
 * What is tolerated, and where it is counted in [stats]:
 * - blank lines and text lines with no number (a banner, a header, a status message): skipped as
 *   [StreamStats.ignoredLines]; lines mixing text and numbers before the first sample (a banner
 *   such as `FSR v2, 4 ch`) as well;
 * - a trailing separator (`1,2,3,`, from sketches printing a comma after every value) and spaces
 *   or tabs around values;
 * - after the first sample, a line with a non-number field is [FrameError.SYNTAX], a line with
 *   another field count [FrameError.FIELD_COUNT], a line over [maxLineLength] bytes
 *   [FrameError.OVERLONG].
 *
 * With [fieldCount] = [AUTO] the count is learned: from a header line (all text, same count as the
 * data line after it), which also gives [channelNames]; otherwise from two consecutive data lines
 * with the same count, so the partial line a board sends when attached mid-stream is not taken as
 * the format. In that case the first sample is delivered one line late.
 *
 * @param separator the field separator; `;`, `\t` or `&` (the LucidGloves legacy encoding) also work.
 * @throws IllegalArgumentException if [fieldCount] is not [AUTO] or in 1..[MAX_FIELDS], if
 *   [maxLineLength] is below 16, or if [separator] is a digit, sign, dot, space or line break.
 */
public class CsvDecoder(
    private val listener: Listener,
    fieldCount: Int = AUTO,
    separator: Char = ',',
    maxLineLength: Int = DEFAULT_MAX_LINE_LENGTH,
) : StreamDecoder {
    /** Receives decoded lines. */
    public fun interface Listener {
        /** Called for each data line; [sample] is reused and valid only during this call. */
        public fun onSample(sample: CsvSample)
    }

    init {
        require(fieldCount == AUTO || fieldCount in 1..MAX_FIELDS) { "fieldCount must be AUTO or in 1..$MAX_FIELDS, was $fieldCount" }
        require(maxLineLength >= 16) { "maxLineLength must be at least 16, was $maxLineLength" }
        require(separator.code in 0x21..0x7E || separator == '\t') { "separator must be printable ASCII or a tab" }
        require(separator !in "0123456789+-.eE ") { "separator '$separator' can be part of a number" }
    }

    override val stats: StreamStats = StreamStats()

    private val fixedFieldCount = fieldCount
    private val separatorByte = separator.code.toByte()
    private val framer = LineFramer(maxLineLength, stats)
    private val sample = CsvSample(MAX_FIELDS)
    private val handler = object : LineHandler {
        override fun onLine(line: ByteArray, length: Int, frameBytes: Int) = decodeLine(line, length, frameBytes)
    }

    private var lockedFieldCount = fieldCount
    private var delivered = false

    // An unconfirmed first data line, while the field count is being learned.
    private val pendingValues = DoubleArray(MAX_FIELDS)
    private val scratchValues = DoubleArray(MAX_FIELDS)
    private var pendingFieldCount = 0
    private var pendingBytes = 0

    // The last all-text line before the field count is known: a header candidate.
    private val headerLine = ByteArray(maxLineLength)
    private var headerLength = 0
    private var headerFieldCount = 0

    /** The field count in use: the one given, or the learned one, or 0 while still learning. */
    public val fieldCount: Int get() = lockedFieldCount

    /** Column names from the header line that fixed the field count, or empty if there was none. */
    public var channelNames: List<String> = emptyList()
        private set

    override fun feed(bytes: ByteArray, offset: Int, length: Int) {
        framer.feed(bytes, offset, length, handler)
    }

    /**
     * Ends the stream: a line still being learned from is delivered (it is complete, just
     * unconfirmed), an unterminated last line is [FrameError.TRUNCATED]; the learned field count and
     * [channelNames] are forgotten.
     */
    override fun finish() {
        if (pendingFieldCount > 0) {
            lockedFieldCount = pendingFieldCount
            deliverPending(keepCurrent = false)
        }
        framer.finish()
        lockedFieldCount = fixedFieldCount
        delivered = false
        headerFieldCount = 0
        channelNames = emptyList()
    }

    private fun decodeLine(line: ByteArray, length: Int, frameBytes: Int) {
        val end = if (length > 0 && line[length - 1] == LineFramer.CR) length - 1 else length
        val values = sample.values
        var fields = 0
        var numbers = 0
        var empty = 0
        var tooMany = false
        var start = 0
        while (true) {
            var stop = start
            while (stop < end && line[stop] != separatorByte) stop++
            var s = start
            var e = stop
            while (s < e && isBlank(line[s])) s++
            while (e > s && isBlank(line[e - 1])) e--
            if (fields == MAX_FIELDS) {
                tooMany = true
            } else if (s == e) {
                empty++
                fields++
            } else {
                val value = Decimal.parse(line, s, e)
                if (!value.isNaN()) {
                    values[fields] = value
                    numbers++
                }
                fields++
            }
            if (stop >= end) break
            start = stop + 1
        }
        if (fields > 1 && empty > 0 && endsWithSeparator(line, end)) {
            fields--
            empty--
        }
        when {
            empty == fields -> stats.ignored(frameBytes)
            tooMany -> reject(FrameError.FIELD_COUNT, frameBytes)
            numbers == 0 && empty == 0 -> onTextLine(line, end, fields, frameBytes)
            numbers != fields -> if (delivered || pendingFieldCount > 0) reject(FrameError.SYNTAX, frameBytes) else stats.ignored(frameBytes)
            else -> onDataLine(fields, frameBytes)
        }
    }

    private fun onTextLine(line: ByteArray, end: Int, fields: Int, frameBytes: Int) {
        stats.ignored(frameBytes)
        if (lockedFieldCount != AUTO && delivered) return
        dropPending()
        line.copyInto(headerLine, 0, 0, end)
        headerLength = end
        headerFieldCount = fields
    }

    private fun onDataLine(fields: Int, frameBytes: Int) {
        sample.fieldCount = fields
        if (lockedFieldCount == AUTO) {
            if (fields == headerFieldCount) {
                lockedFieldCount = fields
                channelNames = headerNames()
            } else if (fields == pendingFieldCount) {
                lockedFieldCount = fields
                deliverPending(keepCurrent = true)
            } else {
                dropPending()
                sample.values.copyInto(pendingValues, 0, 0, fields)
                pendingFieldCount = fields
                pendingBytes = frameBytes
                headerFieldCount = 0
                return
            }
        } else if (!delivered && fields == lockedFieldCount && fields == headerFieldCount && channelNames.isEmpty()) {
            channelNames = headerNames()
        }
        if (fields != lockedFieldCount) {
            reject(FrameError.FIELD_COUNT, frameBytes)
            return
        }
        deliver()
    }

    /** Delivers the pending line; the current line's values, parsed into [sample], are kept aside. */
    private fun deliverPending(keepCurrent: Boolean) {
        val current = sample.fieldCount
        if (keepCurrent) sample.values.copyInto(scratchValues, 0, 0, current)
        pendingValues.copyInto(sample.values, 0, 0, pendingFieldCount)
        sample.fieldCount = pendingFieldCount
        pendingFieldCount = 0
        pendingBytes = 0
        deliver()
        if (keepCurrent) {
            scratchValues.copyInto(sample.values, 0, 0, current)
            sample.fieldCount = current
        }
    }

    private fun deliver() {
        delivered = true
        headerFieldCount = 0
        stats.frames++
        listener.onSample(sample)
    }

    private fun dropPending() {
        if (pendingFieldCount == 0) return
        reject(FrameError.FIELD_COUNT, pendingBytes)
        pendingFieldCount = 0
        pendingBytes = 0
    }

    private fun reject(error: FrameError, frameBytes: Int) = stats.rejected(error, frameBytes)

    private fun headerNames(): List<String> {
        val names = ArrayList<String>(headerFieldCount)
        var start = 0
        while (true) {
            var stop = start
            while (stop < headerLength && headerLine[stop] != separatorByte) stop++
            var s = start
            var e = stop
            while (s < e && isBlank(headerLine[s])) s++
            while (e > s && isBlank(headerLine[e - 1])) e--
            if (s < e || stop < headerLength) names += String(headerLine, s, e - s, Charsets.UTF_8)
            if (stop >= headerLength) break
            start = stop + 1
        }
        return names.take(headerFieldCount)
    }

    private fun endsWithSeparator(line: ByteArray, end: Int): Boolean {
        var e = end
        while (e > 0 && isBlank(line[e - 1])) e--
        return e > 0 && line[e - 1] == separatorByte
    }

    private fun isBlank(b: Byte): Boolean = (b == SPACE || b == TAB) && b != separatorByte

    /** Limits and defaults. */
    public companion object {
        /** Learn the field count from the stream. */
        public const val AUTO: Int = 0

        /** The most fields a line may have. */
        public const val MAX_FIELDS: Int = 64

        /** Default bound on a line's length in bytes, terminator excluded. */
        public const val DEFAULT_MAX_LINE_LENGTH: Int = 1024

        private const val SPACE: Byte = ' '.code.toByte()
        private const val TAB: Byte = '\t'.code.toByte()
    }
}
