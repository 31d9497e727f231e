package org.hapticon.companion.replicate

import org.hapticon.companion.EXIT_OK
import org.hapticon.companion.cli
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.study.analysis.PairedTTest
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

class HapticIconsReplicationTest {
    private val output: String by lazy {
        val result = cli("replicate", "haptic-icons")
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        result.stdout
    }

    private val lines: List<String> by lazy { output.lines() }

    private fun row(prefix: String): String = lines.firstOrNull { it.startsWith(prefix) } ?: throw AssertionError("no line starting '$prefix' in\n$output")

    @Test
    fun table3_asPrinted_withItsRoundedFrequencies_besideBothModels() {
        assertTrue(output, output.startsWith("000 Haptic icons (Wei et al.)"))
        // The paper prints 350 Hz for note 65 (000_f26496a15a0d284b.txt:88) and "-" for hug's period (:91).
        assertTrue(output, lines.contains("stroke  Table 3           1.00000  1.00000  0.300  1.00000      —   65       350   2.600     4"))
        assertTrue(output, lines.contains("hug     Table 3           1.50000  1.00000  0.500  0.50000      —   50       147       -     1"))
        assertTrue(output, lines.contains("        processing model  1.00000  1.00000  0.300  1.00000  1.000   65    349.23   2.600     4"))
        // knock as felt: the attack 221 samples (0.00501 s), the sustain one sample short (440 samples, 0.00998 s).
        assertTrue(output, lines.any { it.startsWith("        processing model  0.00501  0.00998  0.500  0.00501  0.999   57    220.00   0.270     3") })
    }

    private val tables: ReplicationOutput by lazy { ReplicationOutput(output) }

    @Test
    fun frequencies_formulaBesideTheTablesRoundedColumn() {
        assertEquals(listOf("stroke", "65", "350 Hz", "000:88", "349.23 Hz", "349.23 Hz", "the table rounds 349.23 to 350"), tables.row("stroke"))
        assertEquals(listOf("hug", "50", "147 Hz", "000:91", "146.83 Hz", "146.83 Hz", "same, rounded"), tables.row("hug"))
    }

    @Test
    fun processingDefault_statesItsSoundVersionAndTheEvidence() {
        assertTrue(output, output.contains("2.0.1-2.3.1 + JSyn: the paper names only \"the Sound Library in Processing 3\" (000:66, 95)"))
        assertTrue(output, output.contains("(000:175), so the study ran in 2018 or later"))
    }

    @Test
    fun procedure_everyPaperCellCitedOrSilent_noIssueSummary() {
        assertFalse(output, output.contains("issue 14"))
        // rule | paper | cited | hapticon-icons-paper | hapticon-icons | same/different and why
        assertEquals(listOf("16 (4 male, 12 female, aged 25-30)", "000:117", "16", "open"), tables.row("participants").subList(1, 5))
        assertEquals(listOf("000:121", "5-point", "5-point", "same"), tables.row("scale").drop(2))
        assertEquals(listOf("000:125", "white", "none"), tables.row("masking").subList(2, 5))
        assertEquals(listOf("—", "—", "fixed", "williams"), tables.row("stimulus order").subList(1, 5))
        assertTrue(tables.row("stimulus order")[5].startsWith("paper silent"))
        assertEquals("1 stroke, 2 hit, 3 knock, 4 hug", tables.row("icon numbering")[3])
        // Task 2's texts and task 3's stickers are ours: the paper does not publish them.
        assertEquals("ours: the paper does not publish its texts", tables.row("task 2 texts").last())
        val stickers = tables.row("task 3 stickers")
        assertTrue(stickers[3], stickers[3].startsWith("sticker_stroke"))
        assertEquals("ours: the paper does not publish its stickers", stickers.last())
        for (line in tables.lines.drop(tables.indexOf("Procedure:") + 2).takeWhile { it.isNotBlank() }) {
            val cells = tables.cells(line)
            assertTrue(line, Regex("""000:[\d, -]+""").matches(cells[2]) || (cells[2] == "—" && cells[5].startsWith("paper silent")))
        }
    }

    @Test
    fun tTests_thePapersValuesWithTheirP_andTheSimulatedRerunInItsOwnTable() {
        // hit-hug in task 1: t(15) = 2.423 (000_f26496a15a0d284b.txt:145), two-sided p = 0.0285 < 0.05.
        assertEquals(0.0285, PairedTTest.twoSidedP(2.423, 15), 0.0001)
        assertEquals(listOf("icons", "hit-hug", "2.423", "< 0.05", "0.0285"), tables.row("icons"))
        for (published in HapticIconsReplication.PUBLISHED_T) assertTrue(published.pair, PairedTTest.twoSidedP(published.t, 15) < 0.05)
        val heading = lines.indexOfFirst { it.startsWith("SIMULATED, not comparable with the paper's figures: 16 simulated participants through hapticon-icons-paper") }
        assertTrue(output, heading > lines.indexOfFirst { it.startsWith("The paper's paired-sample t tests") })
        // Six pairs per task, named A-B as the paper names them, each over 16 participants with df 15.
        val simulated = HapticIconsReplication.simulatedTTests()
        assertEquals(18, simulated.size)
        assertEquals(listOf("stroke-hit", "stroke-knock", "stroke-hug", "hit-knock", "hit-hug", "knock-hug"), simulated.take(6).map { "${it.iconA}-${it.iconB}" })
        assertTrue(simulated.all { it.tTest!!.n == 16 && it.tTest!!.df == 15 })
    }

    @Test
    fun namedTimes_areDocsEnvelopeModelsTable() {
        // The named times of docs/envelope-models.md, paper / processing: knock's carry shows in its last digit.
        assertTrue(output, lines.contains("knock   2.5, 5, 10, 15, 17.5 ms    0.249 / 0.499    0.500 / 0.999    0.500 / 0.749    0.499 / 0.498    0.249 / 0.248"))
        assertTrue(output, lines.contains("stroke  0.5, 1, 1.5, 2, 2.5 s      0.150 / 0.500    0.300 / 1.000    0.300 / 0.650    0.300 / 0.300    0.150 / 0.150"))
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
