package org.hapticon.gesture.recognition

import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder

class NaoDatasetTest {
    @get:Rule
    val folder = TemporaryFolder()

    private val raw = "time_s,Hand,Lower Arm,upper_arm,SHOULDER\n" + (0 until 10).joinToString("\n") { i -> "${i * 0.025},${11 + i},18,9.5,4" } + "\n"

    @Test
    fun read_fourSensorColumnsAndIndexedPerformances() {
        val indices = "start,end,gesture,intensity,location\n2,5,poking,gentle,hand\n# a discarded trial\n6,9,squeeze,energetic,lower_arm\n"
        val recording = NaoDataset.read("P2", raw, indices)
        assertEquals(10, recording.frameCount)
        assertEquals(15.0, recording.channels[0][4], 0.0)
        assertEquals(4.0, recording.channels[3][9], 0.0)
        assertEquals("[poke-gentle@hand[2, 5), squeeze-energetic@lower-arm[6, 9)]", recording.spans.toString())
    }

    @Test
    fun readDirectory_pairsEachRawFileWithItsIndices() {
        folder.newFile("P3-raw.csv").writeText(raw)
        folder.newFile("P3-indices.csv").writeText("start,end,gesture,intensity,location\n0,10,tickle,gentle,shoulder\n")
        folder.newFile("P2-raw.csv").writeText(raw)
        folder.newFile("P2-indices.csv").writeText("start,end,gesture,intensity,location\n")
        val recordings = NaoDataset.readDirectory(folder.root)
        assertEquals(listOf("P2", "P3"), recordings.map { it.person })
        assertEquals("[tickle-gentle@shoulder[0, 10)]", recordings[1].spans.toString())
        folder.newFile("P4-raw.csv").writeText(raw)
        try {
            NaoDataset.readDirectory(folder.root)
            fail("accepted a raw file without indices")
        } catch (e: IllegalArgumentException) {
            assertEquals("${folder.root}/P4-raw.csv has no P4-indices.csv beside it", e.message)
        }
    }

    @Test
    fun badInput_namesTheFileAndLine() {
        val header = "start,end,gesture,intensity,location\n"
        for ((files, message) in listOf(
            ("hand,lower_arm,upper_arm\n1,2,3\n" to header) to "P-raw.csv:1: no column shoulder in hand,lower_arm,upper_arm",
            ("hand,lower_arm,upper_arm,shoulder\n1,2,3,x\n" to header) to "P-raw.csv:2: shoulder must be a finite resistance >= 0, was \"x\"",
            (raw to "start,end,gesture\n") to "P-indices.csv:1: expected the header start,end,gesture,intensity,location",
            (raw to header + "5,3,hit,gentle,hand\n") to "P-indices.csv:2: need 0 <= start < end <= 10 (the raw file's rows, performances in order), was 5, 3",
            (raw to header + "0,5,hit,gentle,hand\n4,8,hit,gentle,hand\n") to "P-indices.csv:3: need 5 <= start < end <= 10 (the raw file's rows, performances in order), was 4, 8",
            (raw to header + "0,5,wave,gentle,hand\n") to "P-indices.csv:2: unknown gesture 'wave'; expected one of hit, poke, squeeze, stroke, tickle",
            (raw to header + "0,5,hit,soft,hand\n") to "P-indices.csv:2: unknown intensity 'soft'; expected gentle or energetic",
            (raw to header + "0,5,hit,gentle,head\n") to "P-indices.csv:2: unknown location 'head'; expected one of hand, lower_arm, upper_arm, shoulder",
        )) {
            try {
                NaoDataset.read("P", files.first, files.second)
                fail("accepted $files")
            } catch (e: IllegalArgumentException) {
                assertEquals(message, e.message)
            }
        }
    }
}
