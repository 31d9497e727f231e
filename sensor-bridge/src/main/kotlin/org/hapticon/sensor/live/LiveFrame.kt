package org.hapticon.sensor.live

import org.hapticon.sensor.protocol.ProtocolListener
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.stream.StreamDecoder
import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.csv.CsvSample
import org.hapticon.sensor.protocol.decoderFor
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.protocol.lucid.LucidGloveFrame

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
 * One decoded sample of every channel, whatever the protocol. Owned by whoever fills it (the stream,
 * or a recording replayed into a plot) and reused for every sample: valid only during the
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

/**
 * A decoder for [protocol] that hands each decoded frame, with what is known of the stream, to [listener]:
 * the decoding a [SensorSession] runs on its reading thread (without its counters and plot history), for
 * benches that drive a real [FrameListener] such as the grain engine. Frames carry no arrival time.
 */
public fun liveDecoderFor(protocol: SensorProtocol, listener: FrameListener): StreamDecoder =
    LiveDecoder(protocol, sink = { frame, info -> listener.onFrame(frame, info) }).decoder

/**
 * Turns one protocol's decoder callbacks ([decoderFor]) into [LiveFrame]s for [sink], keeping [info]
 * up to date. Used only on the reading thread.
 */
internal class LiveDecoder(
    val protocol: SensorProtocol,
    /** Hears the board's acknowledgements (framed protocol), to settle the commands awaiting them. */
    private val acks: (sequence: Int, status: AckStatus, detail: Int) -> Unit = { _, _, _ -> },
    private val sink: (LiveFrame, StreamInfo) -> Unit,
) : ProtocolListener {
    private val frame = LiveFrame()
    private var csvNames: List<String>? = null

    /** Read by the receiver of a frame; replaced (never mutated) when the stream tells more. */
    @Volatile var info: StreamInfo = StreamInfo(
        protocol,
        if (protocol == SensorProtocol.LUCID_GLOVES) LUCID_FINGER_NAMES else emptyList(),
    )
        private set

    /** Set by the reader before each feed, so frames carry their arrival time. */
    var nowNanos: Long = 0

    val decoder: StreamDecoder = decoderFor(protocol, this)

    // The CSV header's names live on the decoder, not on the sample.
    private val csv = decoder as? CsvDecoder

    override fun onSample(sample: CsvSample) {
        val n = sample.fieldCount
        val names = csv?.channelNames
        if (n != info.channelCount || names !== csvNames) {
            csvNames = names
            info = StreamInfo(protocol, names?.takeIf { it.size == n } ?: defaultNames(n))
        }
        sample.values.copyInto(frame.values, 0, 0, n)
        deliver(n)
    }

    override fun onFrame(frame: LucidGloveFrame) {
        for (f in 0 until LucidGloveFrame.FINGERS) this.frame.values[f] = frame.curl[f].toDouble()
        deliver(LucidGloveFrame.FINGERS)
    }

    override fun onSample(frame: SampleFrame) {
        val n = frame.channelCount
        if (n != info.channelCount) info = StreamInfo(protocol, defaultNames(n))
        for (c in 0 until n) this.frame.values[c] = frame.values[c].toDouble()
        deliver(n)
    }

    override fun onDeviceInfo(info: DeviceInfo) {
        this.info = StreamInfo(
            protocol = protocol,
            channelNames = info.channelUnits.mapIndexed { c, unit -> "ch$c (${unit.symbol})" },
            channelUnits = info.channelUnits,
            adcBits = info.adcBits,
            sampleRateHz = info.sampleRateHz,
            deviceDescription = "${info.name.ifEmpty { "unnamed board" }} · firmware ${info.firmwareVersion} · " +
                "${info.sampleRateHz} Hz · ${info.adcBits}-bit",
        )
    }

    override fun onAck(sequence: Int, status: AckStatus, detail: Int) {
        acks(sequence, status, detail)
    }

    private fun deliver(channels: Int) {
        frame.channelCount = channels
        frame.receivedNanos = nowNanos
        sink(frame, info)
    }

    private fun defaultNames(n: Int): List<String> = List(n) { "ch$it" }

    companion object {
        val LUCID_FINGER_NAMES = listOf("thumb", "index", "middle", "ring", "pinky")
    }
}

/** A short unit label for a framed channel. */
public val ChannelUnit.symbol: String
    get() = when (this) {
        ChannelUnit.RAW -> "raw"
        ChannelUnit.MILLIVOLT -> "mV"
        ChannelUnit.GRAM -> "g"
        ChannelUnit.MILLINEWTON -> "mN"
        ChannelUnit.CENTIDEGREE -> "°"
        ChannelUnit.UNKNOWN -> "?"
    }
