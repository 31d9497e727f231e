package org.hapticon.sensor.protocol.framed

/**
 * One decoded sample frame: all channels read at one instant. The decoder owns and reuses this
 * object: it is valid only until the next frame is delivered, so copy what you keep.
 */
public class SampleFrame internal constructor() {
    /** The frame's sequence number, 0..65535. */
    public var sequence: Int = 0
        internal set

    /**
     * The device's clock when the channels were read, in microseconds. The device sends its 32-bit
     * `micros()`, which wraps every 71.6 minutes; the decoder adds the wraps back, counting from the
     * last device-info frame (a device reboot restarts the clock).
     */
    public var timestampMicros: Long = 0
        internal set

    /** Number of channels in this frame. */
    public var channelCount: Int = 0
        internal set

    /** Channel values 0..65535 in `0 until channelCount`; entries beyond are stale. */
    public val values: IntArray = IntArray(FramedProtocol.MAX_CHANNELS)

    /**
     * The value of [channel].
     * @throws IndexOutOfBoundsException unless [channel] is in `0 until channelCount`.
     */
    public operator fun get(channel: Int): Int {
        if (channel !in 0 until channelCount) throw IndexOutOfBoundsException("channel $channel of $channelCount")
        return values[channel]
    }

    /** Sequence, time and values, for tests and logs. Allocates. */
    override fun toString(): String =
        "SampleFrame(sequence=$sequence, timestampMicros=$timestampMicros, values=${values.copyOf(channelCount).joinToString(",")})"
}
