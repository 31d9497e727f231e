package org.hapticon.app.gesture

import org.hapticon.gesture.Recording
import org.hapticon.sensor.live.ChannelHistory

/**
 * Records from one [GestureSource] at a time into a [RecordingBuffer] of at most [maxSeconds], plotting
 * into [history]. Used by the recorder and the teach flow; [start] and [stop] are called on the main
 * thread, the frames arrive on the source's thread.
 */
class SourceRecorder(val maxSeconds: Double, val history: ChannelHistory = ChannelHistory()) {
    init {
        require(maxSeconds.isFinite() && maxSeconds > 0.0) { "maxSeconds must be finite and > 0, was $maxSeconds" }
    }

    private var source: GestureSource? = null
    private var buffer: RecordingBuffer? = null

    /** True between [start] and [stop]. */
    val recording: Boolean get() = source != null

    /** Frames recorded so far (kept after [stop] until the next [start]). */
    val frames: Int get() = buffer?.frames ?: 0

    /** Seconds recorded so far. */
    val seconds: Double get() = buffer?.let { it.frames / it.sampleRate } ?: 0.0

    /** True once the recording reached [maxSeconds]. */
    val full: Boolean get() = buffer?.full ?: false

    /** Starts recording [from]; [IllegalStateException] (from the source) when it cannot start. */
    fun start(from: GestureSource) {
        check(source == null) { "already recording" }
        history.clear()
        val channels = from.channels
        check(channels.isNotEmpty() && from.sampleRate > 0.0) { "${from.label} has no stream to record" }
        val maxFrames = (maxSeconds * from.sampleRate).toLong().coerceIn(2L, Int.MAX_VALUE.toLong()).toInt()
        val newBuffer = RecordingBuffer(channels, from.sampleRate, maxFrames, history)
        from.start(newBuffer)
        buffer = newBuffer
        source = from
    }

    /** Stops the source and returns what was recorded, or null when it was shorter than two frames. */
    fun stop(): Recording? {
        source?.stop()
        source = null
        return buffer?.toRecording()
    }
}
