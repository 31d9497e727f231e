package org.hapticon.sensor.protocol

import org.hapticon.sensor.protocol.csv.CsvDecoder
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.lucid.LucidGloveDecoder
import org.hapticon.testing.RecordedStreams
import org.hapticon.testing.TabSeparatedProtocol
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

/** The protocol registry: each protocol makes its decoder, and its frames reach the sink as [LiveFrame]s. */
class SensorProtocolsTest {
    private val heard = ArrayList<String>()
    private val sink = object : FrameSink {
        override fun onFrame(frame: LiveFrame, info: StreamInfo) {
            heard += "${info.protocol.cliName} " + (0 until frame.channelCount).joinToString(",") { frame[it].toString() }
        }

        override fun onInfo(info: StreamInfo) {
            heard += "info ${info.deviceDescription}"
        }
    }

    @Test
    fun csv_isACsvDecoderHandingOverEachLine() {
        val decoder = SensorProtocol.CSV.decoder(sink)
        decoder.feed("1,2\n3,4\n".toByteArray())

        assertTrue(decoder is CsvDecoder)
        assertEquals(listOf("csv 1.0,2.0", "csv 3.0,4.0"), heard)
    }

    @Test
    fun lucidGloves_isALucidDecoderHandingOverEachCurl() {
        val decoder = SensorProtocol.LUCID_GLOVES.decoder(sink)
        decoder.feed("A1B2C3D4E5\n".toByteArray())

        assertTrue(decoder is LucidGloveDecoder)
        assertEquals(listOf("lucid 1.0,2.0,3.0,4.0,5.0"), heard)
    }

    @Test
    fun framed_isAFramedDecoderHandingOverDeviceInfoAndSamples() {
        val decoder = SensorProtocol.FRAMED.decoder(sink)
        decoder.feed(RecordedStreams.bytes(RecordedStreams.FRAMED_CLEAN))

        assertTrue(decoder is FramedDecoder)
        assertEquals("info hapticon-ref · firmware 1.0.0 · 1000 Hz · 12-bit", heard.first())
        assertEquals(20, heard.drop(1).size)
        assertTrue(heard.drop(1).all { it.startsWith("framed ") && it.split(',').size == 5 })
    }

    @Test
    fun cliNames_areTheDecodeCommandsChoices() {
        assertEquals(listOf("csv", "lucid", "framed"), SensorProtocols.DEFAULT.cliChoices.keys.toList())
        assertEquals(SensorProtocol.LUCID_GLOVES, SensorProtocols.DEFAULT.cliChoices["lucid"])
    }

    @Test
    fun exampleProtocol_oneFileAndOneRow_isChosenByItsNameAndDecodes() {
        val registry = TabSeparatedProtocol.WITH_EXAMPLE
        assertEquals(listOf("csv", "lucid", "framed", "tabs"), registry.cliChoices.keys.toList())

        val names = ArrayList<List<String>>()
        val decoder = registry.cliChoices.getValue("tabs").decoder(object : FrameSink {
            override fun onFrame(frame: LiveFrame, info: StreamInfo) {
                heard += (0 until frame.channelCount).joinToString(",") { frame[it].toString() }
                names += info.channelNames
            }
        })
        decoder.feed("1\t2.5\n-3\t4\n".toByteArray())

        assertEquals(listOf("1.0,2.5", "-3.0,4.0"), heard)
        assertEquals(listOf("tab0", "tab1"), names.last())
    }

    @Test
    fun registry_twoProtocolsWithOneName_isRefused() {
        val e = assertThrows(IllegalArgumentException::class.java) { SensorProtocols.DEFAULT + SensorProtocol.CSV }
        assertEquals("two protocols share a CLI name: [csv, lucid, framed, csv]", e.message)
    }
}
