package org.hapticon.companion.replicate

import org.hapticon.companion.cli
import org.hapticon.companion.cli.UsageException
import org.hapticon.gesture.recognition.NaoPreset
import org.hapticon.gesture.recognition.NaoRecording
import org.hapticon.gesture.recognition.NaoSpan
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.ByteArrayOutputStream
import java.io.PrintStream

class NaoReplicationTest {
    @get:Rule
    val folder = TemporaryFolder()

    /** A person pressing each sensor in turn, a squeeze on the hand and a gentle tickle on the shoulder, 10 s apart. */
    private fun person(name: String): NaoRecording {
        val n = 1600
        val channels = List(4) { c -> DoubleArray(n) { k -> if (k / 400 == c && k % 400 in 100..299) 5.0 + (k % (3 + c)) else 10.0 + 0.01 * (k % 5) } }
        return NaoRecording(name, channels, (0 until 4).map { c -> NaoSpan(c * 400 + 100, c * 400 + 300, if (c % 2 == 0) "squeeze-energetic" else "tickle-gentle", NaoPreset.LOCATIONS[c]) })
    }

    private fun run(vararg args: String): String {
        val bytes = ByteArrayOutputStream()
        NaoGesturesReplication { listOf(person("a"), person("b")) }.run(PrintStream(bytes, true, "UTF-8"), args.toList())
        return bytes.toString("UTF-8")
    }

    @Test
    fun simulated_printsThePapersFiguresAloneAndOursInItsOwnTable() {
        val out = ReplicationOutput(run())
        assertTrue(out.text, out.text.startsWith("paper text: 004_7d5078645d142b2a.txt, cited as 004:LINE"))
        // The paper's figures, cited, in a table without ours: what | paper | cited | chance.
        val figures = out.indexOf("The paper's figures")
        assertEquals(listOf("combined: average label accuracy", "74.1 %, about 8.2x chance", "004:209-215", "9.1 %"), out.row("combined: average label accuracy", figures))
        assertEquals(listOf("intensity: average label accuracy", "89.3 %", "004:205", "33.3 %"), out.row("intensity: average label accuracy", figures))
        assertEquals(listOf("gentle tickling -> gentle poking", "11 %", "004:215", "—"), out.row("gentle tickling -> gentle poking", figures))
        assertTrue(out.text, out.text.contains("74.1 % / (100 % / 11) = 8.15: \"about 8.2 times higher than the chance\" (004:209-215)."))
        // Ours under the simulated heading, never in a paper column.
        val heading = out.indexOf("SIMULATED, not comparable with the paper's figures: 2 simulated people")
        assertTrue(out.text, heading > figures)
        assertEquals(listOf("what", "ours, random 70/30", "ours, leave one person out", "chance"), out.cells(out.lines[heading + 1]))
        assertEquals("33.3 %", out.row("intensity: accuracy", heading).last())
        assertEquals("20.0 %", out.row("location recall, shoulder", heading).last())
        assertFalse(out.text, out.text.contains("our reading"))
    }

    @Test
    fun rules_citeTheProtocolFeaturesAndSayWhatTheTextLacks() {
        val out = ReplicationOutput(run())
        val protocol = out.row("protocol")
        assertEquals("004:152", protocol[2])
        assertTrue(protocol[3], protocol[3].contains("120 performances a person"))
        assertEquals("004:168", out.row("features")[2])
        assertTrue(out.row("features")[1].contains("number of peaks"))
        val forest = out.row("forest parameters")
        assertEquals("004:174-199", forest[2])
        assertEquals("location 50/40, intensity 100/20, gesture 100/40, combined 100/32; 20 features/split, min split 8, min leaf 1, gini, bootstrap, seeded", forest[3])
        assertEquals(listOf("location 5, intensity 3, gesture 6, combined 11", "same"), out.row("classes").drop(3))
    }

    @Test
    fun data_theStudysLayout_putsOursBesideThePapersFigures() {
        for (name in listOf("P2", "P3")) {
            val p = person(name)
            folder.newFile("$name-raw.csv").writeText(
                "hand,lower_arm,upper_arm,shoulder\n" + (0 until p.frameCount).joinToString("\n") { k -> (0 until 4).joinToString(",") { c -> p.channels[c][k].toString() } } + "\n",
            )
            folder.newFile("$name-indices.csv").writeText(
                "start,end,gesture,intensity,location\n" + p.spans.joinToString("\n") { s -> "${s.from},${s.to},${s.gesture},${s.intensity},${s.location.replace('-', '_')}" } + "\n",
            )
        }
        val out = ReplicationOutput(run("--data", folder.root.path))
        val beside = out.indexOf("The paper's figures beside ours on ${folder.root.path}: 2 participants, 8 performances, 78 windows (the paper: 15, 1683):")
        // what | paper | cited | ours 70/30 | ours LOPO | chance
        val tickle = out.row("gentle tickling recall", beside)
        assertEquals(listOf("64 % (the lowest)", "004:215"), tickle.subList(1, 3))
        assertTrue(tickle.toString(), tickle.subList(3, 5).all { Regex("""\d+\.\d %""").matches(it) })
        assertEquals("9.1 %", tickle.last())
        assertEquals(listOf("—", "—"), out.row("intensity: accuracy", beside).subList(1, 3))
        assertFalse(out.text, out.text.contains("SIMULATED"))
    }

    @Test
    fun data_badDirectoryOrOptions_areOneLineUsageErrors() {
        for ((args, message) in listOf(
            listOf("--data", folder.root.path) to "${folder.root.path} holds no *-raw.csv file",
            listOf("--fast") to "replicate 004 takes [--data DIR], got --fast",
        )) {
            try {
                run(*args.toTypedArray())
                fail("accepted $args")
            } catch (e: UsageException) {
                assertEquals(message, e.message)
            }
        }
        val result = cli("replicate", "nao", "--data", folder.root.path + "/missing")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: ${folder.root.path}/missing is not a directory"), result.stderrLines)
        assertEquals("", result.stdout)
    }
}
