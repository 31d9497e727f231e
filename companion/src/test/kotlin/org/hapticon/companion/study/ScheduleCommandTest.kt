package org.hapticon.companion.study

import org.hapticon.companion.cli
import org.hapticon.study.OriginatingStudy
import org.hapticon.study.ProtocolJson
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder

class ScheduleCommandTest {
    @get:Rule
    val temp = TemporaryFolder()

    @Test
    fun schedule_paperTwoParticipants_exactOutput() {
        val result = cli("schedule", "--participants", "2", "--design", "paper")
        assertEquals(result.toString(), 0, result.exitCode)
        val (tasks, stimuli) = result.stdout.split("\n\n")
        assertEquals(
            "participant,position,task\nP000-A,1,icons\nP000-A,2,text\nP000-A,3,stickers\nP001-D,1,icons\nP001-D,2,stickers\nP001-D,3,text",
            tasks,
        )
        val lines = stimuli.lines()
        assertEquals("participant,task,position,stimulus", lines[0])
        assertEquals(listOf("P000-A,icons,1,stroke", "P000-A,icons,2,hit", "P000-A,icons,3,hug", "P000-A,icons,4,knock"), lines.subList(1, 5))
        assertEquals("P001-D,stickers,1,sticker_hit", lines[13 + 4])
        assertEquals(1 + 2 * 12 + 1, lines.size) // header, 24 rows, the empty string after the last line break
        assertEquals(
            listOf("schedule: 2 participants, paper task order over 2 tasks, cycle of 2 participants: balanced"),
            result.stderrLines,
        )
    }

    @Test
    fun schedule_random_seedReproducible_andDiffers() {
        val a = cli("schedule", "--participants", "6", "--design", "random", "--seed", "7")
        val b = cli("schedule", "--participants", "6", "--design", "random", "--seed", "7")
        val c = cli("schedule", "--participants", "6", "--design", "random", "--seed", "-8")
        assertEquals(0, a.exitCode)
        assertEquals(a.stdout, b.stdout)
        assertNotEquals(a.stdout, c.stdout)
        assertEquals(listOf("schedule: 6 participants, random task order (seeded shuffle, balanced only on average)"), a.stderrLines)
    }

    @Test
    fun schedule_protocolFile_williamsOverThreeTasks() {
        val protocol = OriginatingStudy.PROTOCOL.copy(fixedFirst = emptyList())
        val file = temp.newFile("p.json").apply { writeText(ProtocolJson.encode(protocol)) }
        val result = cli("schedule", "--participants", "5", "--design", "williams", "--protocol", file.path)
        assertEquals(result.toString(), 0, result.exitCode)
        val taskRows = result.stdout.substringBefore("\n\n").lines().drop(1)
        assertEquals(15, taskRows.size)
        assertEquals(listOf("P001-D,1,text", "P001-D,2,stickers", "P001-D,3,icons"), taskRows.subList(3, 6))
        assertEquals(
            listOf("schedule: 5 participants, williams task order over 3 tasks, cycle of 6 participants: not balanced: not a multiple of the cycle"),
            result.stderrLines,
        )
    }

    @Test
    fun schedule_errors_exit2WithOneLine() {
        fun error(vararg args: String): String {
            val result = cli("schedule", *args)
            assertEquals(result.toString(), 2, result.exitCode)
            assertEquals(result.toString(), "", result.stdout)
            return result.stderrLines.single()
        }
        assertEquals("hapticon: schedule needs --participants", error("--design", "paper"))
        assertEquals("hapticon: schedule needs --design", error("--participants", "3"))
        assertEquals("hapticon: --participants must be a whole number in 1..100000, got '0'", error("--participants", "0", "--design", "paper"))
        assertEquals("hapticon: --participants must be a whole number in 1..100000, got '1e3'", error("--participants", "1e3", "--design", "paper"))
        assertEquals(
            "hapticon: --design must be fixed or paper or full or williams or random, got 'latin'",
            error("--participants", "3", "--design", "latin"),
        )
        assertEquals("hapticon: --seed must be a whole number (64-bit), got 'x'", error("--participants", "3", "--design", "random", "--seed", "x"))
        val missing = temp.root.resolve("none.json").path
        assertEquals("hapticon: --protocol: no such file: $missing", error("--participants", "3", "--design", "paper", "--protocol", missing))
        val bad = temp.newFile("bad.json").apply { writeText(ProtocolJson.encode(OriginatingStudy.PROTOCOL).replace("\"points\": 5", "\"points\": 1")) }
        assertEquals(
            "hapticon: protocol file ${bad.path} is not a valid study protocol: scale.points: must be in 2..11, was 1",
            error("--participants", "3", "--design", "paper", "--protocol", bad.path),
        )
        val notJson = temp.newFile("not.json").apply { writeText("{") }
        assertEquals(
            "hapticon: protocol file ${notJson.path} is not valid JSON: unexpected end of input, expected a member name in double quotes at offset 1",
            error("--participants", "3", "--design", "paper", "--protocol", notJson.path),
        )
    }

    @Test
    fun studyProtocol_printsTheDefault_andWritesAFile() {
        val printed = cli("study-protocol")
        assertEquals(0, printed.exitCode)
        assertEquals(OriginatingStudy.PROTOCOL, ProtocolJson.decode(printed.stdout))
        val out = temp.root.resolve("protocol.json")
        val written = cli("study-protocol", "--out", out.path)
        assertEquals(0, written.exitCode)
        assertEquals(printed.stdout, out.readText())
        assertEquals(listOf("study-protocol: wrote ${out.path}"), written.stderrLines)
        assertEquals(2, cli("study-protocol", "extra").exitCode)
    }
}
