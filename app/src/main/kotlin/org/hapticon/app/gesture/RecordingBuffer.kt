package org.hapticon.app.gesture

import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import org.hapticon.sensor.live.ChannelHistory
import org.hapticon.sensor.protocol.LiveFrame

/**
 * Collects the frames of one recording from a [GestureSource] (a [GestureSink], written on the source's
 * thread) up to [maxFrames] per channel: memory is bounded by `maxFrames × channels` doubles, grown in
 * steps so a short recording stays small. Frames past the limit are dropped and [full] turns true.
 * Every frame also goes to [history] (with a time stamp from the frame count, so the plot's time axis is
 * the recording's) for the live plot.
 */
class RecordingBuffer(
    private val channels: List<GestureChannel>,
    val sampleRate: Double,
    val maxFrames: Int,
    private val history: ChannelHistory? = null,
) : GestureSink {
    init {
        require(channels.isNotEmpty()) { "a recording needs at least one channel" }
        require(sampleRate.isFinite() && sampleRate > 0.0) { "sample rate must be finite and > 0 Hz, was $sampleRate" }
        require(maxFrames >= 1) { "maxFrames must be >= 1, was $maxFrames" }
    }

    private val lock = Any()
    private var data = Array(channels.size) { DoubleArray(minOf(maxFrames, INITIAL_FRAMES)) }
    private val plotFrame = LiveFrame()

    /** Frames stored so far. */
    @Volatile var frames: Int = 0
        private set

    /** True once [maxFrames] were stored; later frames are dropped. */
    val full: Boolean get() = frames >= maxFrames

    override fun onFrame(values: DoubleArray) {
        synchronized(lock) {
            if (frames >= maxFrames) return
            if (frames == data[0].size) {
                val grown = minOf(maxFrames.toLong(), 2L * data[0].size).toInt()
                data = Array(data.size) { data[it].copyOf(grown) }
            }
            for (c in data.indices) data[c][frames] = values[c]
            frames++
        }
        history?.let {
            val n = minOf(values.size, LiveFrame.MAX_CHANNELS)
            plotFrame.channelCount = n
            values.copyInto(plotFrame.values, 0, 0, n)
            plotFrame.receivedNanos = (frames * 1e9 / sampleRate).toLong()
            it.append(plotFrame)
        }
    }

    /** The frames so far as a recording, or null before the second frame (a recording needs a length). */
    fun toRecording(): Recording? = synchronized(lock) {
        if (frames < 2) return null
        Recording(sampleRate, channels.mapIndexed { c, channel -> Channel(channel.name, channel.unit, data[c].copyOf(frames), channel.fullScale) })
    }

    private companion object {
        const val INITIAL_FRAMES = 4096
    }
}
