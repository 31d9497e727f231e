package org.hapticon.sensor.live

import org.hapticon.sensor.protocol.stream.FrameError
import org.hapticon.sensor.protocol.stream.StreamStats
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.protocol.StreamInfo

/** The decoder's counters and what happened to the commands sent to the board, copied for the UI. */
public data class StreamCounters(
    val bytes: Long = 0,
    val frames: Long = 0,
    val badFrames: Long = 0,
    val droppedBytes: Long = 0,
    val ignoredLines: Long = 0,
    val sequenceGaps: Long = 0,
    val lostFrames: Long = 0,
    /** Frames cut short by the end of the stream (an unplug mid-frame). */
    val truncatedFrames: Long = 0,
    /** Commands written to the board ([CommandWriter]). */
    val commandsSent: Long = 0,
    /** Commands the board acknowledged. */
    val commandsAcknowledged: Long = 0,
    /** Commands the board refused (NACK). */
    val commandsRejected: Long = 0,
    /** Commands the board never answered within the ack timeout, or before the stream stopped. */
    val commandsTimedOut: Long = 0,
    /** Commands whose write failed. */
    val commandsLost: Long = 0,
    /** Settings replaced by a newer one of the same key before they were written (nothing lost). */
    val commandsSuperseded: Long = 0,
    /** Events refused because the writer's queue was full. */
    val commandsOverflowed: Long = 0,
    /** Well-formed acks for no command awaiting one. */
    val unmatchedAcks: Long = 0,
    /** Ack frames of the wrong length (also in [badFrames]). */
    val malformedAcks: Long = 0,
)

/** What the stream holds now, copied for the UI. */
public data class StreamSnapshot(
    val info: StreamInfo?,
    /** The newest value of each channel. */
    val latest: List<Double>,
    val counters: StreamCounters,
    /** Samples received since connecting; changes whenever the plots have something new. */
    val samples: Long,
    /** Frames per second over the last second, or null before a second has passed. */
    val measuredRateHz: Double?,
)

/**
 * The running tally of one stream: the newest value of each channel, the stream info, the decoder's
 * counters and the measured frame rate. Written on the reading thread, copied by [snapshot] on any
 * other; nothing is allocated per frame or per read.
 */
internal class StreamTally {
    private val lock = Any()

    // Guarded by lock.
    private val latest = DoubleArray(LiveFrame.MAX_CHANNELS)
    private var latestCount = 0
    private var info: StreamInfo? = null
    private var bytes = 0L
    private var frames = 0L
    private var badFrames = 0L
    private var droppedBytes = 0L
    private var ignoredLines = 0L
    private var sequenceGaps = 0L
    private var lostFrames = 0L
    private var truncated = 0L
    private var malformedAcks = 0L
    private var rateWindowStart = 0L
    private var rateWindowSamples = 0L
    private var samples = 0L
    private var measuredRate = Double.NaN

    /** Forgets everything (a new connection). */
    fun reset() {
        synchronized(lock) {
            latestCount = 0
            info = null
            bytes = 0; frames = 0; badFrames = 0; droppedBytes = 0; ignoredLines = 0
            sequenceGaps = 0; lostFrames = 0; truncated = 0; malformedAcks = 0
            rateWindowStart = 0; rateWindowSamples = 0; samples = 0; measuredRate = Double.NaN
        }
    }

    /** Counts [frame] and keeps its values; the rate is measured over windows of at least a second. */
    fun onFrame(frame: LiveFrame, frameInfo: StreamInfo) {
        synchronized(lock) {
            val n = frame.channelCount
            frame.values.copyInto(latest, 0, 0, n)
            latestCount = n
            if (info !== frameInfo) info = frameInfo
            samples++
            val now = frame.receivedNanos
            if (rateWindowStart == 0L) {
                rateWindowStart = now
                rateWindowSamples = samples
            } else if (now - rateWindowStart >= RATE_WINDOW_NANOS) {
                measuredRate = (samples - rateWindowSamples) * 1e9 / (now - rateWindowStart)
                rateWindowStart = now
                rateWindowSamples = samples
            }
        }
    }

    /** Copies the decoder's counters, so bad frames show even when no good one follows. */
    fun copyStats(stats: StreamStats) {
        synchronized(lock) {
            bytes = stats.bytes
            frames = stats.frames
            badFrames = stats.badFrames
            droppedBytes = stats.droppedBytes
            ignoredLines = stats.ignoredLines
            sequenceGaps = stats.sequenceGaps
            lostFrames = stats.lostFrames
            truncated = stats.badFrames(FrameError.TRUNCATED)
            malformedAcks = stats.malformedAcks
        }
    }

    /** Shows [streamInfo] at once when it tells something, even before any sample (device info). */
    fun publishInfo(streamInfo: StreamInfo) {
        synchronized(lock) {
            if (info !== streamInfo && (streamInfo.channelCount > 0 || streamInfo.deviceDescription != null)) info = streamInfo
        }
    }

    fun currentInfo(): StreamInfo? = synchronized(lock) { info }

    /** What the stream holds now, with [commands]' counts beside the decoder's. */
    fun snapshot(commands: CommandCounts = CommandCounts()): StreamSnapshot = synchronized(lock) {
        StreamSnapshot(
            info = info,
            latest = List(latestCount) { latest[it] },
            counters = StreamCounters(
                bytes, frames, badFrames, droppedBytes, ignoredLines, sequenceGaps, lostFrames, truncated,
                commandsSent = commands.sent,
                commandsAcknowledged = commands.acknowledged,
                commandsRejected = commands.rejected,
                commandsTimedOut = commands.timedOut,
                commandsLost = commands.lost,
                commandsSuperseded = commands.superseded,
                commandsOverflowed = commands.overflowed,
                unmatchedAcks = commands.unmatchedAcks,
                malformedAcks = malformedAcks,
            ),
            samples = samples,
            measuredRateHz = measuredRate.takeUnless { it.isNaN() },
        )
    }

    private companion object {
        const val RATE_WINDOW_NANOS = 1_000_000_000L
    }
}
