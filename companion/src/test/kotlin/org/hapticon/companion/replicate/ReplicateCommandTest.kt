package org.hapticon.companion.replicate

import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.cli
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.HapticIcon
import org.hapticon.companion.EXIT_OK
import org.hapticon.gesture.recognition.NaoRecording
import org.hapticon.gesture.recognition.NaoSpan
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import java.io.ByteArrayOutputStream
import java.io.PrintStream

class ReplicateCommandTest {
    /** A replication that prints a fixed line, to test the dispatch alone. */
    private class TestReplication(override val id: String) : Replication {
        override val title: String = "test $id"
        override fun run(out: PrintStream) = out.println("ran $id")
    }

    private fun run(vararg args: String): String {
        val bytes = ByteArrayOutputStream()
        val out = PrintStream(bytes, true, "UTF-8")
        runReplicate(args.toList(), Console(out, out), listOf(TestReplication("001"), TestReplication("002")))
        return bytes.toString("UTF-8")
    }

    @Test
    fun replicate_byId_runsThatOneWithItsTitle() {
        assertEquals("002 test 002\nran 002\n", run("002"))
    }

    @Test
    fun replicate_noId_listsThem() {
        assertEquals("001  test 001\n002  test 002\n", run())
    }

    @Test
    fun replicate_unknownId_isAUsageError() {
        try {
            run("009")
            fail("accepted")
        } catch (e: UsageException) {
            assertEquals("no replication '009'; try 001, 002", e.message)
        }
        val result = cli("replicate", "009")
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: no replication '009'; try 000, 001, 002, 003, 004"), result.stderrLines)
    }

    @Test
    fun allReplications_areInIdOrder() {
        assertEquals(listOf("000", "001", "002", "003", "004"), allReplications.map { it.id })
    }

    @Test
    fun handshake_twoTakes_lowerTheFitErrorByAboutRootTwo() {
        val (alpha1, beta1) = HandshakeCalibrationReplication.rmsErrors(1)
        val (alpha2, beta2) = HandshakeCalibrationReplication.rmsErrors(2)
        // Averaging two independent pose errors halves their variance: errors fall by ≈ √2 (1.3..1.6 over 500 trials).
        assertTrue("$alpha1 vs $alpha2", alpha1 / alpha2 in 1.3..1.6)
        assertTrue("$beta1 vs $beta2", beta1 / beta2 in 1.3..1.6)
    }

    @Test
    fun handshake_namesThePaperAndSaysItsMethodsWereNotChecked() {
        val bytes = ByteArrayOutputStream()
        HandshakeCalibrationReplication.run(PrintStream(bytes, true, "UTF-8"))
        val lines = bytes.toString("UTF-8").lines()
        assertEquals(
            "source: \"Tele Haptic Handshake Using Distributed Pressure Presentation Device and Mutual Interaction " +
                "Pressure Model\", Electronics 14(3):537, 2025, doi:10.3390/electronics14030537",
            lines[1],
        )
        assertTrue(lines.joinToString("\n"), lines[3].startsWith("         its Methods were not reached"))
        assertTrue(lines.joinToString("\n"), lines.any { it.startsWith("  divider fixed resistor   not reached (see docs)   33") })
    }

    @Test
    fun nao_onTwoTinySessions_printsTheTable() {
        val still = { person: String ->
            NaoRecording(person, List(4) { c -> DoubleArray(400) { k -> if (k in 100..299) 5.0 + c + (k % 7) else 10.0 } }, listOf(NaoSpan(100, 300, "squeeze-gentle")))
        }
        val bytes = ByteArrayOutputStream()
        NaoGesturesReplication { listOf(still("a"), still("b")) }.run(PrintStream(bytes, true, "UTF-8"))
        val text = bytes.toString("UTF-8")
        assertTrue(text, text.contains("combined (11 classes)          74.1 %"))
        assertTrue(text, text.contains("data: 2 simulated people"))
        assertTrue(text, text.contains("the 31st feature per channel (number of peaks) is our reading"))
    }

    @Test
    fun socialTouch_onTwoSimulatedPeople_printsAllThreeClassSetsBesideThePapersColumn() {
        val bytes = ByteArrayOutputStream()
        SocialTouchReplication(people = 2, takesPerClass = 2).run(PrintStream(bytes, true, "UTF-8"))
        val text = bytes.toString("UTF-8")
        // 2 people × 2 takes × 6 classes = 24 messages per six-class set; 13 classes make 52.
        val row = Regex("""  (6 emotions|6 social messages|13 classes \(incl. no touch\))\s+n/t\s+(\d+\.\d) %\s+(\d+\.\d) %\s+\(chance (\d+\.\d) %, (\d+) messages\)""")
        val rows = row.findAll(text).map { it.groupValues }.toList()
        assertEquals(text, listOf("6 emotions", "6 social messages", "13 classes (incl. no touch)"), rows.map { it[1] })
        assertEquals(listOf("24", "24", "52"), rows.map { it[5] })
        assertEquals(listOf("16.7", "16.7", "7.7"), rows.map { it[4] })
        for (r in rows) assertTrue(text, r[2].toDouble() in 0.0..100.0 && r[3].toDouble() in 0.0..100.0)
        assertTrue(text, text.contains("anger disgust fear happiness sadness sympathy"))
    }

    @Test
    fun replicate_withoutId_listsTheReplications() {
        val result = cli("replicate")
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        assertTrue(result.stdout, result.stdout.startsWith("000  Haptic icons (Wei et al.)"))
        assertTrue(result.stdout, result.stdout.contains("\n001  Shaping Compliance"))
    }

    @Test
    fun replicate000_printsTable3BesideBothModelsAndTheProcedures() {
        val result = cli("replicate", "000")
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        val lines = result.stdout.lines()
        assertTrue(result.stdout, lines.contains("stroke  Table 3           1.00000  1.00000  0.300  1.00000      —    349.23   2.600     4"))
        assertTrue(result.stdout, lines.contains("        processing model  1.00000  1.00000  0.300  1.00000  1.000    349.23   2.600     4"))
        // knock as felt: the attack 221 samples (0.00501 s), the sustain one sample short (440 samples, 0.00998 s), the release to the disconnection at 882.
        assertTrue(result.stdout, lines.any { it.startsWith("        processing model  0.00501  0.00998  0.500  0.00501  0.999    220.00   0.270     3") })
        assertTrue(result.stdout, lines.any { it.startsWith("participants     | 16 ") && it.contains("| issue 14 ") && it.endsWith("| open") })
        // The named times of docs/envelope-models.md, paper / processing: knock's carry shows in its last digit.
        assertTrue(result.stdout, lines.contains("knock   2.5, 5, 10, 15, 17.5 ms    0.249 / 0.499    0.500 / 0.999    0.500 / 0.749    0.499 / 0.498    0.249 / 0.248"))
        assertTrue(result.stdout, lines.contains("stroke  0.5, 1, 1.5, 2, 2.5 s      0.150 / 0.500    0.300 / 1.000    0.300 / 0.650    0.300 / 0.300    0.150 / 0.150"))
        assertTrue(result.stdout, lines.any { it.startsWith("masking ") && it.contains("| white ") && it.endsWith("| none") })
    }

    @Test
    fun measure_processingKnock_seesTheShortenedSustainInSamples() {
        // knock's processing sustain at 44.1 kHz: samples 221..661, one short of 0.01 s after the phase carry.
        val knock = HapticIconsReplication.measure(HapticIcon.KNOCK, EnvelopeModel.PROCESSING)
        assertEquals(221 / 44_100.0, knock.attack, 1e-12)
        assertEquals((661 - 221) / 44_100.0, knock.sustain, 1e-12)
        assertEquals(3, knock.count)
        assertEquals(0.27, knock.period, 1e-12)
        assertEquals(220.0, knock.frequency, 0.01)
        val paperStroke = HapticIconsReplication.measure(HapticIcon.STROKE, EnvelopeModel.PAPER)
        assertEquals(0.3, paperStroke.peak, 1e-12)
        assertEquals(2.6, paperStroke.period, 1e-9)
    }
}
