package org.hapticon.app.sensors

import org.hapticon.sensor.protocol.StreamDecoder
import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.protocol.lucid.LucidGloveDecoder
import org.hapticon.sensor.protocol.lucid.LucidGloveFrame

/** The byte protocols a board may speak (docs/protocols.md). */
enum class SensorProtocol(val label: String) {
    /** Lines of numbers, as Arduino sketches print them. */
    CSV("CSV"),

    /** The LucidGloves / OpenGloves alpha encoding: curls A..E per line. */
    LUCID_GLOVES("LucidGloves"),

    /** The Hapticon framed binary protocol (COBS + CRC), with device info. */
    FRAMED("Framed"),
}

/** Baud rates offered in the UI; 1200 is left out on purpose (it reboots native-USB boards). */
val BAUD_RATES: List<Int> = listOf(9_600, 19_200, 38_400, 57_600, 115_200, 230_400, 460_800, 921_600)

/**
 * What is known about the stream: names and units of its channels, and what the board said about
 * itself (framed protocol only). Immutable; replaced only when something changes.
 */
data class StreamInfo(
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
    val channelCount: Int get() = channelNames.size
}

/**
 * One decoded sample of every channel, whatever the protocol. Owned by the stream and reused for
 * every sample: valid only during the [FrameListener] call.
 */
class LiveFrame internal constructor() {
    /** Number of channels in [values]. */
    var channelCount: Int = 0
        internal set

    /** Channel values in `0 until channelCount`, as the board sent them (counts, mV, g, …). */
    val values: DoubleArray = DoubleArray(MAX_CHANNELS)

    /** [System.nanoTime]-style arrival time of the bytes that completed this frame. */
    var receivedNanos: Long = 0
        internal set

    operator fun get(channel: Int): Double = values[channel]

    companion object {
        /** The most channels a line may carry (CSV's limit). */
        const val MAX_CHANNELS: Int = CsvDecoder.MAX_FIELDS
    }
}

/** Hears every decoded frame, on the sensor's reading thread. Must not block, should not allocate. */
fun interface FrameListener {
    fun onFrame(frame: LiveFrame, info: StreamInfo)
}

/**
 * Turns one protocol's decoder callbacks into [LiveFrame]s for [sink], keeping [info] up to date.
 * Used only on the reading thread.
 */
internal class ProtocolAdapter(
    val protocol: SensorProtocol,
    private val sink: (LiveFrame, StreamInfo) -> Unit,
) {
    private val frame = LiveFrame()
    private var csvNames: List<String>? = null

    /** Read by the receiver of a frame; replaced (never mutated) when the stream tells more. */
    @Volatile var info: StreamInfo = StreamInfo(protocol, emptyList())
        private set

    /** Set by the reader before each feed, so frames carry their arrival time. */
    var nowNanos: Long = 0

    val decoder: StreamDecoder = when (protocol) {
        SensorProtocol.CSV -> {
            lateinit var csv: CsvDecoder
            csv = CsvDecoder({ sample ->
                val n = sample.fieldCount
                if (n != info.channelCount || csv.channelNames !== csvNames) {
                    csvNames = csv.channelNames
                    val names = csv.channelNames.takeIf { it.size == n } ?: defaultNames(n)
                    info = StreamInfo(protocol, names)
                }
                sample.values.copyInto(frame.values, 0, 0, n)
                deliver(n)
            })
            csv
        }
        SensorProtocol.LUCID_GLOVES -> {
            info = StreamInfo(protocol, LUCID_FINGER_NAMES)
            LucidGloveDecoder({ lucid ->
                for (f in 0 until LucidGloveFrame.FINGERS) frame.values[f] = lucid.curl[f].toDouble()
                deliver(LucidGloveFrame.FINGERS)
            })
        }
        SensorProtocol.FRAMED -> FramedDecoder(object : FramedDecoder.Listener {
            override fun onSample(frame: SampleFrame) = onFramedSample(frame)
            override fun onDeviceInfo(info: DeviceInfo) = onFramedInfo(info)
        })
    }

    private fun onFramedSample(sample: SampleFrame) {
        val n = sample.channelCount
        if (n != info.channelCount) info = StreamInfo(protocol, defaultNames(n))
        for (c in 0 until n) frame.values[c] = sample.values[c].toDouble()
        deliver(n)
    }

    private fun onFramedInfo(device: DeviceInfo) {
        info = StreamInfo(
            protocol = protocol,
            channelNames = device.channelUnits.mapIndexed { c, unit -> "ch$c (${unit.symbol})" },
            channelUnits = device.channelUnits,
            adcBits = device.adcBits,
            sampleRateHz = device.sampleRateHz,
            deviceDescription = "${device.name.ifEmpty { "unnamed board" }} · firmware ${device.firmwareVersion} · " +
                "${device.sampleRateHz} Hz · ${device.adcBits}-bit",
        )
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
val ChannelUnit.symbol: String
    get() = when (this) {
        ChannelUnit.RAW -> "raw"
        ChannelUnit.MILLIVOLT -> "mV"
        ChannelUnit.GRAM -> "g"
        ChannelUnit.MILLINEWTON -> "mN"
        ChannelUnit.CENTIDEGREE -> "°"
        ChannelUnit.UNKNOWN -> "?"
    }
