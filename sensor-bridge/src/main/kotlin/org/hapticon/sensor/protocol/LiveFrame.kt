package org.hapticon.sensor.protocol

import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.framed.ChannelUnit

/**
 * What is known about the stream: names and units of its channels, and what the board said about
 * itself (framed protocol only). Immutable; replaced only when something changes.
 */
public data class StreamInfo(
    val protocol: SensorProtocol,
    val channelNames: List<String>,
    /** Per channel, framed protocol only; null otherwise. */
    val channelUnits: List<ChannelUnit>? = null,
    /** From device info (framed protocol only). */
    val adcBits: Int? = null,
    /** From device info (framed protocol only). */
    val sampleRateHz: Int? = null,
    /** The board's name and firmware, from device info. */
    val deviceDescription: String? = null,
) {
    /** How many channels the stream carries. */
    val channelCount: Int get() = channelNames.size
}

/**
 * One decoded sample of every channel, whatever the protocol. Owned by whoever fills it (a protocol's
 * decoder, or a recording replayed into a plot) and reused for every sample: valid only during the
 * [FrameListener] call.
 */
public class LiveFrame {
    /** Number of channels in [values]. */
    public var channelCount: Int = 0

    /** Channel values in `0 until channelCount`, as the board sent them (counts, mV, g, …). */
    public val values: DoubleArray = DoubleArray(MAX_CHANNELS)

    /** [System.nanoTime]-style arrival time of the bytes that completed this frame. */
    public var receivedNanos: Long = 0

    /** The value of [channel]. */
    public operator fun get(channel: Int): Double = values[channel]

    public companion object {
        /** The most channels a line may carry (CSV's limit). */
        public const val MAX_CHANNELS: Int = CsvDecoder.MAX_FIELDS
    }
}

/** Hears every decoded frame, on the sensor's reading thread. Must not block, should not allocate. */
public fun interface FrameListener {
    /** One frame; [frame] is reused and valid only during this call. */
    public fun onFrame(frame: LiveFrame, info: StreamInfo)
}
