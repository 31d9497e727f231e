package org.hapticon.companion.sensors

import kotlinx.serialization.json.JsonObject
import org.hapticon.core.io.SchemaJson
import org.hapticon.sensor.protocol.ProtocolListener
import org.hapticon.sensor.protocol.csv.CsvSample
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.protocol.lucid.LucidGloveFrame
import java.io.Writer

/** Listens to any of the decoders and writes each frame to [out] as one line of compact JSON ([FrameJson]). */
class JsonLinesListener(private val out: Writer) : ProtocolListener {
    override fun onSample(sample: CsvSample) = write(FrameJson.csv(sample))

    override fun onFrame(frame: LucidGloveFrame) = write(FrameJson.lucid(frame))

    override fun onSample(frame: SampleFrame) = write(FrameJson.sample(frame))

    override fun onDeviceInfo(info: DeviceInfo) = write(FrameJson.deviceInfo(info))

    override fun onAck(sequence: Int, status: AckStatus, detail: Int) = write(FrameJson.ack(sequence, status, detail))

    /** Writes [value] as one line. */
    fun write(value: JsonObject) {
        out.write(SchemaJson.encodeElement(value))
        out.write("\n")
    }
}
