package org.hapticon.sensor.protocol

import kotlinx.serialization.SerialName
import kotlinx.serialization.Serializable
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.protocol.framed.symbol
import org.hapticon.sensor.protocol.stream.StreamDecoder

/**
 * The Hapticon framed binary protocol (COBS + CRC-16, docs/protocols.md): samples, the board's device info (which
 * names the channels by unit and gives its ADC bits and rate) and its acks to commands. Its decoder is a
 * [FramedDecoder]; `hapticon decode` writes `sample`, `device_info` and `ack` documents.
 */
public data object FramedBinaryProtocol : SensorProtocol {
    override val label: String get() = "Framed"

    override val cliName: String get() = "framed"

    override fun decoder(sink: FrameSink): StreamDecoder = FramedDecoder(FramedFrames(sink))
}

private class FramedFrames(private val sink: FrameSink) : FramedDecoder.Listener {
    private val frame = LiveFrame()
    private var info = FramedBinaryProtocol.initialInfo()

    override fun onSample(frame: SampleFrame) {
        val n = frame.channelCount
        if (n != info.channelCount) info = StreamInfo(FramedBinaryProtocol, channelNumbers(n))
        for (c in 0 until n) this.frame.values[c] = frame.values[c].toDouble()
        this.frame.channelCount = n
        sink.onFrame(this.frame, info)
        sink.documents?.write(SampleDocument.serializer(), SampleDocument(sequence = frame.sequence, timestampMicros = frame.timestampMicros, channels = frame.values.copyOf(n).asList()))
    }

    override fun onDeviceInfo(info: DeviceInfo) {
        this.info = StreamInfo(
            protocol = FramedBinaryProtocol,
            channelNames = info.channelUnits.mapIndexed { c, unit -> "ch$c (${unit.symbol})" },
            channelUnits = info.channelUnits,
            adcBits = info.adcBits,
            sampleRateHz = info.sampleRateHz,
            deviceDescription = "${info.name.ifEmpty { "unnamed board" }} · firmware ${info.firmwareVersion} · " +
                "${info.sampleRateHz} Hz · ${info.adcBits}-bit",
        )
        sink.onInfo(this.info)
        sink.documents?.write(DeviceInfoDocument.serializer(), DeviceInfoDocument.of(info))
    }

    override fun onAck(sequence: Int, status: AckStatus, detail: Int) {
        sink.onAck(sequence, status, detail)
        sink.documents?.write(AckDocument.serializer(), AckDocument(commandSequence = sequence, status = status.name.lowercase(), detail = detail))
    }
}

/** `{"type":"sample","seq":N,"timestamp_us":N,"channels":[...]}`: one framed sample. */
@Serializable
internal class SampleDocument(
    val type: String = "sample",
    @SerialName("seq") val sequence: Int,
    @SerialName("timestamp_us") val timestampMicros: Long,
    val channels: List<Int>,
)

/** `{"type":"device_info",...}`: the firmware version, ADC bits, rate, outputs, channel units and name. */
@Serializable
internal class DeviceInfoDocument(
    val type: String = "device_info",
    val name: String,
    val firmware: String,
    @SerialName("adc_bits") val adcBits: Int,
    @SerialName("sample_rate_hz") val sampleRateHz: Int,
    val outputs: Int,
    @SerialName("channel_units") val channelUnits: List<String>,
) {
    companion object {
        fun of(info: DeviceInfo): DeviceInfoDocument = DeviceInfoDocument(
            name = info.name,
            firmware = info.firmwareVersion,
            adcBits = info.adcBits,
            sampleRateHz = info.sampleRateHz,
            outputs = info.outputCount,
            channelUnits = info.channelUnits.map { it.name.lowercase() },
        )
    }
}

/** `{"type":"ack","command_seq":N,"status":"ok","detail":N}`: the board's answer to the command numbered `command_seq`. */
@Serializable
internal class AckDocument(
    val type: String = "ack",
    @SerialName("command_seq") val commandSequence: Int,
    val status: String,
    val detail: Int,
)
