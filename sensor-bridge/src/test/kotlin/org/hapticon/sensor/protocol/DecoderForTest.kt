package org.hapticon.sensor.protocol

import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.csv.CsvSample
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.protocol.lucid.LucidGloveDecoder
import org.hapticon.sensor.protocol.lucid.LucidGloveFrame
import org.hapticon.testing.RecordedStreams
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

/** The one protocol dispatch: each protocol gets its decoder, and its frames reach the listener. */
class DecoderForTest {
    private val heard = ArrayList<String>()
    private val listener = object : ProtocolListener {
        override fun onSample(sample: CsvSample) {
            heard += "csv " + (0 until sample.fieldCount).joinToString(",") { sample.values[it].toString() }
        }

        override fun onFrame(frame: LucidGloveFrame) {
            heard += "lucid " + frame.curl.joinToString(",")
        }

        override fun onSample(frame: SampleFrame) {
            heard += "framed ${frame.channelCount}"
        }

        override fun onDeviceInfo(info: DeviceInfo) {
            heard += "info ${info.name}"
        }
    }

    @Test
    fun csv_isACsvDecoderHandingOverEachLine() {
        val decoder = decoderFor(SensorProtocol.CSV, listener)
        decoder.feed("1,2\n3,4\n".toByteArray())

        assertTrue(decoder is CsvDecoder)
        assertEquals(listOf("csv 1.0,2.0", "csv 3.0,4.0"), heard)
    }

    @Test
    fun lucidGloves_isALucidDecoderHandingOverEachCurl() {
        val decoder = decoderFor(SensorProtocol.LUCID_GLOVES, listener)
        decoder.feed("A1B2C3D4E5\n".toByteArray())

        assertTrue(decoder is LucidGloveDecoder)
        assertEquals(listOf("lucid 1,2,3,4,5"), heard)
    }

    @Test
    fun framed_isAFramedDecoderHandingOverDeviceInfoAndSamples() {
        val decoder = decoderFor(SensorProtocol.FRAMED, listener)
        decoder.feed(RecordedStreams.bytes(RecordedStreams.FRAMED_CLEAN))

        assertTrue(decoder is FramedDecoder)
        assertEquals("info hapticon-ref", heard.first())
        assertEquals(List(20) { "framed 5" }, heard.drop(1))
    }

    @Test
    fun cliNames_areTheDecodeCommandsChoices() {
        assertEquals(listOf("csv", "lucid", "framed"), SensorProtocol.CLI_CHOICES.keys.toList())
        assertEquals(SensorProtocol.LUCID_GLOVES, SensorProtocol.CLI_CHOICES["lucid"])
    }
}
