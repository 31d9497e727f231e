package org.hapticon.sensor.protocol

import org.hapticon.sensor.protocol.stream.StreamDecoder
import org.hapticon.sensor.protocol.stream.StreamStats
import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.csv.CsvSample
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.protocol.lucid.LucidGloveDecoder
import org.hapticon.sensor.protocol.lucid.LucidGloveFrame

/** Collects decoded frames as text, copying them out of the decoders' reused objects. */
class Recorder : CsvDecoder.Listener, LucidGloveDecoder.Listener, FramedDecoder.Listener {
    val events = ArrayList<String>()
    val samples = ArrayList<List<Double>>()
    val infos = ArrayList<DeviceInfo>()

    override fun onSample(sample: CsvSample) {
        samples += sample.values.copyOf(sample.fieldCount).toList()
        events += sample.toString()
    }

    override fun onFrame(frame: LucidGloveFrame) {
        events += frame.toString()
    }

    override fun onSample(frame: SampleFrame) {
        events += "sample ${frame.sequence} t=${frame.timestampMicros} ${frame.values.copyOf(frame.channelCount).joinToString(",")}"
    }

    override fun onDeviceInfo(info: DeviceInfo) {
        infos += info
        events += "info ${info.name}"
    }

    override fun onAck(sequence: Int, status: AckStatus, detail: Int) {
        events += "ack $sequence $status $detail"
    }
}

/** Feeds [bytes] in pieces of [chunk] bytes. */
fun StreamDecoder.feedInChunks(bytes: ByteArray, chunk: Int) {
    var offset = 0
    while (offset < bytes.size) {
        val n = minOf(chunk, bytes.size - offset)
        feed(bytes, offset, n)
        offset += n
    }
}

fun ascii(text: String): ByteArray = text.toByteArray(Charsets.ISO_8859_1)

/** Every counter of [stats] as one comparable string. */
fun StreamStats.summary(): String = toString()
