package org.hapticon.sensor.live

import org.hapticon.sensor.protocol.LiveFrame

/**
 * Where a live plot reads its points from. (Compose's strong skipping compares implementations by
 * identity, so this plain interface needs no `@Stable` to keep a plot from recomposing.)
 */
public interface PlotSource {
    /**
     * Copies channel [channel]'s samples of the last [windowNanos] before the newest sample, oldest
     * first: x in [0, 1] across the window into [xOut], the value into [yOut]. Returns how many were
     * copied (at most the arrays' size). Allocation-free.
     */
    public fun copyRecent(channel: Int, windowNanos: Long, xOut: FloatArray, yOut: FloatArray): Int
}

/** A plot source with nothing in it, for previews and screens without a stream. */
public object EmptyPlotSource : PlotSource {
    override fun copyRecent(channel: Int, windowNanos: Long, xOut: FloatArray, yOut: FloatArray): Int = 0
}

/**
 * The last [capacity] samples of up to [maxChannels] channels with their arrival times, in
 * preallocated ring buffers: written by the reading thread, read by the UI when it draws. Nothing is
 * allocated per sample or per draw.
 */
public class ChannelHistory(public val capacity: Int = DEFAULT_CAPACITY, public val maxChannels: Int = DEFAULT_MAX_CHANNELS) : PlotSource {
    private val lock = Any()
    private val values = Array(maxChannels) { FloatArray(capacity) }
    private val times = LongArray(capacity)
    private var next = 0
    private var size = 0

    /** Samples written since the last [clear]. */
    @Volatile public var written: Long = 0
        private set

    /** Appends [frame] (its first [maxChannels] channels). */
    public fun append(frame: LiveFrame) {
        synchronized(lock) {
            val channels = minOf(frame.channelCount, maxChannels)
            for (c in 0 until channels) values[c][next] = frame.values[c].toFloat()
            for (c in channels until maxChannels) values[c][next] = Float.NaN
            times[next] = frame.receivedNanos
            next = (next + 1) % capacity
            if (size < capacity) size++
            written++
        }
    }

    /** Forgets every sample. */
    public fun clear() {
        synchronized(lock) {
            next = 0
            size = 0
            written = 0
        }
    }

    override fun copyRecent(channel: Int, windowNanos: Long, xOut: FloatArray, yOut: FloatArray): Int {
        if (channel !in 0 until maxChannels) return 0
        synchronized(lock) {
            if (size == 0) return 0
            val newest = (next - 1 + capacity) % capacity
            val end = times[newest]
            val start = end - windowNanos
            // Walk back to the oldest sample inside the window (and that fits the output).
            val limit = minOf(size, xOut.size, yOut.size)
            var count = 0
            while (count < limit) {
                val i = (newest - count + capacity) % capacity
                if (times[i] < start) break
                count++
            }
            val column = values[channel]
            for (k in 0 until count) {
                val i = (newest - count + 1 + k + capacity) % capacity
                xOut[k] = if (windowNanos > 0) ((times[i] - start).toDouble() / windowNanos).toFloat() else 1f
                yOut[k] = column[i]
            }
            return count
        }
    }

    public companion object {
        /** 4096 samples: 4 s at 1 kHz, longer at slower rates. */
        public const val DEFAULT_CAPACITY: Int = 4096

        /** Channels beyond this are shown as numbers only. */
        public const val DEFAULT_MAX_CHANNELS: Int = 16
    }
}
