package org.hapticon.sensor.protocol.stream

/**
 * Counters kept by a decoder over the life of its stream (they survive [StreamDecoder.finish]).
 *
 * Every byte fed ends up either in a delivered frame, in [droppedBytes], or still buffered in an
 * unfinished frame, so `bytes − droppedBytes − buffered` is what the frames carried.
 *
 * Not thread-safe: read it on the thread that feeds the decoder (the [StreamDecoder] listener and
 * [org.hapticon.sensor.port.SensorReader] callbacks run there) or take a [snapshot] there.
 */
public class StreamStats {
    /** Bytes fed to the decoder. */
    public var bytes: Long = 0
        internal set

    /** Frames (samples, lines) delivered to the listener. */
    public var frames: Long = 0
        internal set

    /** Complete frames rejected, for any [FrameError]; see [badFrames] for one kind. */
    public var badFrames: Long = 0
        internal set

    /** Bytes that did not end up in a delivered frame: garbage, rejected frames, banners, idle delimiters. */
    public var droppedBytes: Long = 0
        internal set

    /** Text lines skipped on purpose (banner, header, blank line, status message), included in [droppedBytes]. */
    public var ignoredLines: Long = 0
        internal set

    /** Times a sequence number was not the expected one (framed protocol only). */
    public var sequenceGaps: Long = 0
        internal set

    /**
     * Frames missing according to the sequence numbers, summed over all [sequenceGaps]; a jump back
     * (or forward by 32768 or more) counts as a gap with nothing lost.
     */
    public var lostFrames: Long = 0
        internal set

    /**
     * Acknowledgement frames with a good CRC but the wrong payload length (framed protocol only; also counted in
     * [badFrames] as [FrameError.FIELD_COUNT]): an ack that cannot be matched to its command.
     */
    public var malformedAcks: Long = 0
        internal set

    private val byError = LongArray(FrameError.entries.size)

    /** The number of frames rejected because of [error]. */
    public fun badFrames(error: FrameError): Long = byError[error.ordinal]

    /** A copy of the current counts, for handing to another thread. Allocates. */
    public fun snapshot(): StreamStats {
        val copy = StreamStats()
        copy.bytes = bytes
        copy.frames = frames
        copy.badFrames = badFrames
        copy.droppedBytes = droppedBytes
        copy.ignoredLines = ignoredLines
        copy.sequenceGaps = sequenceGaps
        copy.lostFrames = lostFrames
        copy.malformedAcks = malformedAcks
        byError.copyInto(copy.byError)
        return copy
    }

    internal fun rejected(error: FrameError, byteCount: Int) {
        badFrames++
        byError[error.ordinal]++
        droppedBytes += byteCount
    }

    internal fun ignored(byteCount: Int) {
        ignoredLines++
        droppedBytes += byteCount
    }

    /** Lists every counter, and each non-zero [FrameError] count. */
    override fun toString(): String = buildString {
        append("StreamStats(bytes=").append(bytes).append(", frames=").append(frames)
        append(", badFrames=").append(badFrames).append(", droppedBytes=").append(droppedBytes)
        append(", ignoredLines=").append(ignoredLines).append(", sequenceGaps=").append(sequenceGaps)
        append(", lostFrames=").append(lostFrames)
        if (malformedAcks != 0L) append(", malformedAcks=").append(malformedAcks)
        for (error in FrameError.entries) {
            val count = byError[error.ordinal]
            if (count != 0L) append(", ").append(error.name).append('=').append(count)
        }
        append(')')
    }
}
