package org.hapticon.companion.sensors

import org.hapticon.companion.cli
import org.hapticon.testing.RecordedStreams
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File

class DecodeCommandTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun recorded(name: String): File = temp.newFile(name).also { it.writeBytes(RecordedStreams.bytes(name)) }

    private fun decode(protocol: String, file: File): List<String> {
        val result = cli("decode", "--protocol", protocol, "--in", file.path)
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals("", result.stderr)
        return result.stdout.lines().dropLast(1)
    }

    @Test
    fun decode_csvWithGarbage_printsEveryGoodLineThenCountsTheRest() {
        val lines = decode("csv", recorded(RecordedStreams.CSV_GARBAGE_CRLF))
        val expected = listOf(
            """{"type":"csv","values":[512,498,1023]}""",
            """{"type":"csv","values":[511,497,1022]}""",
            """{"type":"csv","values":[507.5,494.25,1019]}""",
        ) + (0 until 10).map { k -> """{"type":"csv","values":[${500 + k},${480 + k},${1000 + k}]}""" } + (
            """{"stats":{"frames":13,"bad_frames":6,"dropped_bytes":1109,"bytes":1299,"ignored_lines":2,"sequence_gaps":0,""" +
                """"lost_frames":0,"bad_frames_by_error":{"overlong":1,"field_count":2,"syntax":2,"truncated":1}}}"""
            )
        assertEquals(expected, lines)
    }

    @Test
    fun decode_csvWithBannerAndHeader_skipsThemAsIgnoredLines() {
        val lines = decode("csv", recorded(RecordedStreams.CSV_BANNER_HEADER))
        assertEquals(21, lines.size)
        assertEquals("""{"type":"csv","values":[0,211,422,633]}""", lines[0])
        assertEquals("""{"type":"csv","values":[703,914,101,312]}""", lines[19])
        assertEquals(
            """{"stats":{"frames":20,"bad_frames":0,"dropped_bytes":63,"bytes":376,"ignored_lines":3,"sequence_gaps":0,"lost_frames":0,"bad_frames_by_error":{}}}""",
            lines[20],
        )
    }

    @Test
    fun decode_lucidGloves_printsOnlyTheFieldsEachLineCarried() {
        val lines = decode("lucid", recorded(RecordedStreams.LUCIDGLOVES))
        val expected = listOf(
            """{"type":"lucid","fingers":[0,577,1154,1731,2308],"joystick":[2048,2047],"trigger":288}""",
            """{"type":"lucid","fingers":[151,728,1305,1882,2459],"joystick":[2049,2046],"trigger":364}""",
            """{"type":"lucid","fingers":[302,879,1456,2033,2610],"joystick":[2050,2045],"trigger":439}""",
            """{"type":"lucid","fingers":[453,1030,1607,2184,2761],"joystick":[2051,2044],"trigger":515}""",
            """{"type":"lucid","fingers":[604,1181,1758,2335,2912],"joystick":[2052,2043],"trigger":590,""" +
                """"buttons":["joystick_click","trigger","a","b","grab","pinch","menu","calibrate"]}""",
            """{"type":"lucid","fingers":[755,1332,1909,2486,3063],"joystick":[2053,2042],"trigger":666,"buttons":["a","grab"],""" +
                """"splay":[2053,2063,2073,2083,2093]}""",
            """{"type":"lucid","fingers":[906,1483,2060,2637,3214],"trigger":741,""" +
                """"joints":[[null,1234,null,null],[null,null,null,null],[null,null,null,null],[null,null,null,null],[null,null,null,null]]}""",
            """{"type":"lucid","fingers":[1057,1634,2211,2788,3365],"joystick":[2055,2040],"trigger":817,"buttons":["trigger"]}""",
            """{"type":"lucid","fingers":[1208,1785,2362,2939,3516],"joystick":[2056,2039],"trigger":892,"buttons":["trigger"]}""",
            """{"type":"lucid","fingers":[1359,1936,2513,3090,3667],"joystick":[2057,2038],"trigger":968,"buttons":["trigger"]}""",
            """{"stats":{"frames":10,"bad_frames":2,"dropped_bytes":50,"bytes":491,"ignored_lines":1,"sequence_gaps":0,"lost_frames":0,""" +
                """"bad_frames_by_error":{"field_count":1,"syntax":1}}}""",
        )
        assertEquals(expected, lines)
    }

    @Test
    fun decode_framedClean_printsDeviceInfoSamplesAndAck() {
        val lines = decode("framed", recorded(RecordedStreams.FRAMED_CLEAN))
        assertEquals(23, lines.size)
        assertEquals(
            """{"type":"device_info","name":"hapticon-ref","firmware":"1.0.0","adc_bits":12,"sample_rate_hz":1000,"outputs":5,""" +
                """"channel_units":["raw","raw","raw","gram","centidegree"]}""",
            lines[0],
        )
        // generate.py: sample k has sequence k + 1, time 1 s + k ms, channel c = (97k + 331c + 13kc) mod 4096.
        for (k in 0 until 20) {
            val channels = (0 until 5).joinToString(",") { c -> ((k * 97 + c * 331 + k * c * 13) % 4096).toString() }
            assertEquals("""{"type":"sample","seq":${k + 1},"timestamp_us":${1_000_000 + 1000 * k},"channels":[$channels]}""", lines[1 + k])
        }
        assertEquals("""{"type":"ack","command_seq":7,"status":"ok","detail":0}""", lines[21])
        assertEquals(
            """{"stats":{"frames":22,"bad_frames":0,"dropped_bytes":1,"bytes":488,"ignored_lines":0,"sequence_gaps":0,"lost_frames":0,"bad_frames_by_error":{}}}""",
            lines[22],
        )
    }

    @Test
    fun decode_framedSequenceGap_countsTheGapAndTheLostFrames() {
        val lines = decode("framed", recorded(RecordedStreams.FRAMED_SEQUENCE_GAP))
        assertEquals(
            """{"stats":{"frames":18,"bad_frames":0,"dropped_bytes":0,"bytes":409,"ignored_lines":0,"sequence_gaps":1,"lost_frames":3,"bad_frames_by_error":{}}}""",
            lines.last(),
        )
        // Samples k = 10..12 (sequence numbers 11..13) are missing: sequence 10 is followed by 14.
        val sequences = lines.subList(1, lines.size - 1).map { Regex("\"seq\":(\\d+),").find(it)!!.groupValues[1].toInt() }
        assertEquals((1..10).toList() + (14..20).toList(), sequences)
    }

    @Test
    fun decode_framedUnplugged_keepsWholeFramesAndCountsTheTruncatedOne() {
        val lines = decode("framed", recorded(RecordedStreams.FRAMED_UNPLUG))
        assertEquals(12, lines.size)
        assertEquals(
            """{"stats":{"frames":11,"bad_frames":1,"dropped_bytes":9,"bytes":264,"ignored_lines":0,"sequence_gaps":0,"lost_frames":0,"bad_frames_by_error":{"truncated":1}}}""",
            lines.last(),
        )
    }

    @Test
    fun decode_textAsFramed_isGarbageNotAnError() {
        val lines = decode("framed", recorded(RecordedStreams.LUCIDGLOVES))
        assertEquals(
            listOf("""{"stats":{"frames":0,"bad_frames":1,"dropped_bytes":491,"bytes":491,"ignored_lines":0,"sequence_gaps":0,"lost_frames":0,"bad_frames_by_error":{"truncated":1}}}"""),
            lines,
        )
    }

    @Test
    fun decode_emptyFile_printsOnlyZeroStats() {
        val lines = decode("csv", temp.newFile("empty.csv"))
        assertEquals(
            listOf("""{"stats":{"frames":0,"bad_frames":0,"dropped_bytes":0,"bytes":0,"ignored_lines":0,"sequence_gaps":0,"lost_frames":0,"bad_frames_by_error":{}}}"""),
            lines,
        )
    }

    @Test
    fun decode_fileLargerThanOneRead_decodesLinesAcrossReadBoundaries() {
        // About 1.5 MB: 23 reads of 64 KiB, so lines straddle many read boundaries.
        val rows = 150_000
        val file = temp.newFile("long.csv")
        file.bufferedWriter().use { w -> for (i in 0 until rows) w.write("$i,${i % 1024}\n") }
        val lines = decode("csv", file)
        assertEquals(rows + 1, lines.size)
        assertEquals("""{"type":"csv","values":[65535,1023]}""", lines[65_535])
        assertEquals("""{"type":"csv","values":[149999,495]}""", lines[rows - 1])
        assertEquals(
            """{"stats":{"frames":150000,"bad_frames":0,"dropped_bytes":0,"bytes":${file.length()},"ignored_lines":0,"sequence_gaps":0,"lost_frames":0,"bad_frames_by_error":{}}}""",
            lines.last(),
        )
    }

    @Test
    fun decode_missingFile_exitsTwoNamingIt() {
        val missing = File(temp.root, "none.bin")
        val result = cli("decode", "--protocol", "framed", "--in", missing.path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: --in: no such file: $missing"), result.stderrLines)
        assertEquals("", result.stdout)
    }

    @Test
    fun decode_directory_exitsTwo() {
        val result = cli("decode", "--protocol", "framed", "--in", temp.root.path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: --in: ${temp.root} is a directory, not a file"), result.stderrLines)
    }

    @Test
    fun decode_unknownProtocol_exitsTwoListingTheChoices() {
        val result = cli("decode", "--protocol", "xml", "--in", recorded(RecordedStreams.FRAMED_CLEAN).path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: --protocol must be csv or lucid or framed, got 'xml'"), result.stderrLines)
        assertEquals("", result.stdout)
    }

    @Test
    fun decode_withoutProtocolOrFile_exitsTwo() {
        val noProtocol = cli("decode", "--in", "x.bin")
        assertEquals(2, noProtocol.exitCode)
        assertEquals(listOf("hapticon: decode needs --protocol csv|lucid|framed"), noProtocol.stderrLines)
        val noFile = cli("decode", "--protocol", "LUCID")
        assertEquals(2, noFile.exitCode)
        assertEquals(listOf("hapticon: decode needs --in"), noFile.stderrLines)
    }
}
