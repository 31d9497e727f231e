package org.hapticon.sensor.protocol.lucid

import org.hapticon.sensor.protocol.stream.FrameError
import org.hapticon.sensor.protocol.stream.LineFramer
import org.hapticon.sensor.protocol.stream.LineHandler
import org.hapticon.sensor.protocol.stream.StreamDecoder
import org.hapticon.sensor.protocol.stream.StreamStats

/**
 * Decodes the LucidGloves / OpenGloves "alpha" encoding, one newline-terminated line per frame:
 * `A<n>B<n>C<n>D<n>E<n>` curls thumb..pinky, `F<n>G<n>` joystick, `P<n>` analog trigger, the
 * presence-only [LucidButton] letters `H`..`O`, and the bracketed keys `(AB)<n>`..`(EB)<n>` (splay)
 * and `(AAA)<n>`..`(EAD)<n>` (per-joint curl). Keys may come in any order; a repeated key keeps its
 * last value. Keys the encoding does not define (other letters, other bracketed keys) are skipped
 * with their digits, as the OpenGloves driver does.
 *
 * Counted in [stats] instead of delivered: a line missing one of `A`..`E` ([FrameError.FIELD_COUNT]),
 * a key that needs digits without them, more than 9 digits, or any character outside `A`..`Z`,
 * digits, brackets and a final `\r` ([FrameError.SYNTAX]); lines over [maxLineLength]
 * ([FrameError.OVERLONG]). Lines that fail before the first good frame are a banner and count as
 * [StreamStats.ignoredLines], as blank lines always do.
 *
 * @throws IllegalArgumentException if [maxLineLength] is below 16.
 */
public class LucidGloveDecoder(
    private val listener: Listener,
    maxLineLength: Int = DEFAULT_MAX_LINE_LENGTH,
) : StreamDecoder {
    /** Receives decoded frames. */
    public fun interface Listener {
        /** Called for each good line; [frame] is reused and valid only during this call. */
        public fun onFrame(frame: LucidGloveFrame)
    }

    init {
        require(maxLineLength >= 16) { "maxLineLength must be at least 16, was $maxLineLength" }
    }

    override val stats: StreamStats = StreamStats()

    private val framer = LineFramer(maxLineLength, stats)
    private val frame = LucidGloveFrame()
    private var delivered = false
    private val handler = object : LineHandler {
        override fun onLine(line: ByteArray, length: Int, frameBytes: Int) = decodeLine(line, length, frameBytes)
    }

    override fun feed(bytes: ByteArray, offset: Int, length: Int) {
        framer.feed(bytes, offset, length, handler)
    }

    override fun finish() {
        framer.finish()
        delivered = false
    }

    private fun decodeLine(line: ByteArray, length: Int, frameBytes: Int) {
        val end = if (length > 0 && line[length - 1] == LineFramer.CR) length - 1 else length
        if (end == 0) {
            stats.ignored(frameBytes)
            return
        }
        val error = parse(line, end)
        when {
            error == null -> {
                delivered = true
                stats.frames++
                listener.onFrame(frame)
            }
            delivered -> stats.rejected(error, frameBytes)
            else -> stats.ignored(frameBytes)
        }
    }

    /** Fills [frame] from the line; returns null if it is good, else why not. */
    private fun parse(line: ByteArray, end: Int): FrameError? {
        frame.clear()
        var curls = 0
        var i = 0
        while (i < end) {
            val c = line[i].toInt()
            if (c in 'A'.code..'Z'.code) {
                i++
                val digitsEnd = digitsEnd(line, i, end)
                val value = if (digitsEnd == i) ABSENT_VALUE else value(line, i, digitsEnd)
                if (value == TOO_LONG) return FrameError.SYNTAX
                i = digitsEnd
                when (c) {
                    in 'A'.code..'E'.code -> {
                        if (value == ABSENT_VALUE) return FrameError.SYNTAX
                        curls = curls or (1 shl (c - 'A'.code))
                        frame.curl[c - 'A'.code] = value
                    }
                    'F'.code, 'G'.code, 'P'.code -> {
                        if (value == ABSENT_VALUE) return FrameError.SYNTAX
                        when (c) {
                            'F'.code -> frame.joystickX = value
                            'G'.code -> frame.joystickY = value
                            else -> frame.trigger = value
                        }
                    }
                    in 'H'.code..'O'.code -> frame.buttons = frame.buttons or (1 shl (c - 'H'.code))
                    // Other letters are keys this encoding does not define: skipped with their digits.
                }
            } else if (c == '('.code) {
                var close = i + 1
                while (close < end && line[close].toInt() in 'A'.code..'Z'.code) close++
                if (close == end || line[close].toInt() != ')'.code) return FrameError.SYNTAX
                val keyStart = i + 1
                val keyLength = close - keyStart
                i = close + 1
                val digitsEnd = digitsEnd(line, i, end)
                if (digitsEnd == i) return FrameError.SYNTAX
                val value = value(line, i, digitsEnd)
                if (value == TOO_LONG) return FrameError.SYNTAX
                i = digitsEnd
                val finger = line[keyStart] - 'A'.code.toByte()
                if (finger !in 0 until LucidGloveFrame.FINGERS) continue
                if (keyLength == 2 && line[keyStart + 1] == 'B'.code.toByte()) {
                    frame.splay[finger] = value
                } else if (keyLength == 3 && line[keyStart + 1] == 'A'.code.toByte()) {
                    val joint = line[keyStart + 2] - 'A'.code.toByte()
                    if (joint in 0 until LucidGloveFrame.JOINTS_PER_FINGER) {
                        frame.jointCurl[finger * LucidGloveFrame.JOINTS_PER_FINGER + joint] = value
                    }
                }
            } else {
                return FrameError.SYNTAX
            }
        }
        return if (curls == ALL_CURLS) null else FrameError.FIELD_COUNT
    }

    private fun digitsEnd(line: ByteArray, start: Int, end: Int): Int {
        var i = start
        while (i < end && line[i] - ZERO in 0..9) i++
        return i
    }

    private fun value(line: ByteArray, start: Int, end: Int): Int {
        if (end - start > MAX_DIGITS) return TOO_LONG
        var value = 0
        for (i in start until end) value = value * 10 + (line[i] - ZERO)
        return value
    }

    /** Defaults. */
    public companion object {
        /** Default bound on a line's length in bytes, terminator excluded (the firmware sends under 100). */
        public const val DEFAULT_MAX_LINE_LENGTH: Int = 256

        private const val MAX_DIGITS = 9
        private const val ABSENT_VALUE = -1
        private const val TOO_LONG = -2
        private const val ALL_CURLS = 0b11111
        private const val ZERO: Byte = '0'.code.toByte()
    }
}
