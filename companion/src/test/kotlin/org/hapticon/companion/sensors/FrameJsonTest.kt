package org.hapticon.companion.sensors

import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.companion.cli.Console
import org.hapticon.sensor.protocol.framed.DeviceInfo
import org.hapticon.sensor.protocol.framed.ChannelUnit
import org.hapticon.testing.TabSeparatedProtocol
import org.junit.Assert.assertEquals
import org.junit.Test
import java.io.ByteArrayOutputStream
import java.io.File
import java.io.PrintStream
import java.io.StringWriter

class FrameJsonTest {
    private fun decode(protocol: SensorProtocol, bytes: ByteArray): List<String> {
        val out = StringWriter()
        val decoder = protocol.decoder(JsonLinesListener(out))
        decoder.feed(bytes)
        decoder.finish()
        return out.toString().lines().dropLast(1)
    }

    @Test
    fun lucid_joystickWithOnlyX_writesNullForY() {
        val lines = decode(SensorProtocol.LUCID_GLOVES, "A1B2C3D4E5F7\n".toByteArray())
        assertEquals(listOf("""{"type":"lucid","fingers":[1,2,3,4,5],"joystick":[7,null]}"""), lines)
    }

    @Test
    fun lucid_partialSplay_writesNullForFingersWithout() {
        val lines = decode(SensorProtocol.LUCID_GLOVES, "A1B2C3D4E5(CB)300(AB)100O\n".toByteArray())
        assertEquals(listOf("""{"type":"lucid","fingers":[1,2,3,4,5],"buttons":["calibrate"],"splay":[100,null,300,null,null]}"""), lines)
    }

    @Test
    fun ack_rejection_namesTheStatusInLowerCase() {
        val frame = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val length = FramedEncoder(firstSequence = 40).ack(sequence = 9, status = AckStatus.OUT_OF_RANGE, detail = 3, destination = frame)
        assertEquals(listOf("""{"type":"ack","command_seq":9,"status":"out_of_range","detail":3}"""), decode(SensorProtocol.FRAMED, frame.copyOf(length)))
    }

    @Test
    fun csv_decimalAndNegativeValues_keepTheirForm() {
        val lines = decode(SensorProtocol.CSV, "-1.5,2,1e3\n0.25,-0,7\n".toByteArray())
        assertEquals(listOf("""{"type":"csv","values":[-1.5,2,1000]}""", """{"type":"csv","values":[0.25,-0,7]}"""), lines)
    }

    @Test
    fun deviceInfo_namesEveryFieldInSnakeCase() {
        val frame = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val info = DeviceInfo(1, 2, 3, adcBits = 12, sampleRateHz = 500, outputCount = 9, channelUnits = listOf(ChannelUnit.RAW, ChannelUnit.GRAM), name = "glove \"L\"")
        val length = FramedEncoder().deviceInfo(info, frame)
        assertEquals(
            listOf("""{"type":"device_info","name":"glove \"L\"","firmware":"1.2.3","adc_bits":12,"sample_rate_hz":500,"outputs":9,"channel_units":["raw","gram"]}"""),
            decode(SensorProtocol.FRAMED, frame.copyOf(length)),
        )
    }

    @Test
    fun decodeCommand_aRegistryWithTheExampleProtocol_takesItsNameAndWritesItsDocuments() {
        val file = File.createTempFile("tabs", ".txt").apply { deleteOnExit(); writeText("1\t2.5\n-3\t4\n") }
        val out = ByteArrayOutputStream()
        PrintStream(out, true, "UTF-8").use { stdout ->
            runDecode(listOf("--protocol", "tabs", "--in", file.path), Console(stdout, System.err), TabSeparatedProtocol.WITH_EXAMPLE)
        }
        val lines = out.toString("UTF-8").lines()
        assertEquals(listOf("""{"type":"tabs","values":[1,2.5]}""", """{"type":"tabs","values":[-3,4]}"""), lines.take(2))
        assertEquals(""""frames":2""", Regex("\"frames\":\\d+").find(lines[2])!!.value)
    }
}
