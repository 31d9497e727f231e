package org.hapticon.sensor.protocol

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import org.hapticon.sensor.protocol.stream.FrameError
import org.hapticon.sensor.protocol.stream.StreamStats

/**
 * `{"stats":{"frames","bad_frames","dropped_bytes","bytes","ignored_lines","sequence_gaps","lost_frames",
 * "bad_frames_by_error":{...}}}`: the last line of `hapticon decode`, whatever the protocol.
 */
@Serializable
public class StreamStatsDocument(
    /** The counters. */
    public val stats: Counts,
) {
    /** A decoder's [StreamStats]; [badFramesByError] holds only the [FrameError] kinds that occurred. */
    @Serializable
    public class Counts(
        public val frames: Long,
        @SerialName("bad_frames") public val badFrames: Long,
        @SerialName("dropped_bytes") public val droppedBytes: Long,
        public val bytes: Long,
        @SerialName("ignored_lines") public val ignoredLines: Long,
        @SerialName("sequence_gaps") public val sequenceGaps: Long,
        @SerialName("lost_frames") public val lostFrames: Long,
        @SerialName("bad_frames_by_error") public val badFramesByError: Map<String, Long>,
    )

    public companion object {
        /** The document of [stats] as they are now. */
        public fun of(stats: StreamStats): StreamStatsDocument {
            val byError = LinkedHashMap<String, Long>()
            for (error in FrameError.entries) {
                val count = stats.badFrames(error)
                if (count != 0L) byError[error.name.lowercase()] = count
            }
            val counts = with(stats) { Counts(frames, badFrames, droppedBytes, bytes, ignoredLines, sequenceGaps, lostFrames, byError) }
            return StreamStatsDocument(counts)
        }
    }
}
