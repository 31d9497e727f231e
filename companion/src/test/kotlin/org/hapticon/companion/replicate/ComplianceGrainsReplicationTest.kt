package org.hapticon.companion.replicate

import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import java.io.ByteArrayOutputStream
import java.io.PrintStream

class ComplianceGrainsReplicationTest {
    private val text: String by lazy {
        val bytes = ByteArrayOutputStream()
        ComplianceGrainsReplication.run(PrintStream(bytes, true, "UTF-8"))
        bytes.toString("UTF-8")
    }

    private fun assertLine(regex: String) = assertTrue(text, Regex(regex).containsMatchIn(text))

    @Test
    fun grains_binsSweptAndGrainsFired_areThePapersRule() {
        for (g in listOf(9, 19, 39)) assertLine("""\n\s+$g\s+${g + 1}\s+$g\n""")
        assertEquals(listOf(9, 19, 39), listOf(9, 19, 39).map { ComplianceGrainsReplication.grainsPerSlowPress(it) })
        assertEquals(listOf(10, 20, 40), listOf(9, 19, 39).map { ComplianceGrainsReplication.binsSwept(it) })
    }

    @Test
    fun deadTime_isTheGrainsDelivery_notTwentyMilliseconds() {
        // 8 ms + 250 µs per electrode; at 1 kHz a rapid press fires at the first sample after it.
        assertLine("""small-square\s+4\s+9\.00 ms\s+9\.00 ms\s+9 ms""")
        assertLine("""horizontal-line\s+6\s+9\.50 ms\s+9\.50 ms\s+10 ms""")
        assertLine("""large-square\s+9\s+10\.25 ms\s+10\.25 ms\s+11 ms""")
        assertEquals(11, ComplianceGrainsReplication.rapidPressSpacingMillis(ElectrodeMask.LARGE_SQUARE))
        assertTrue(text, !text.contains("20 ms"))
    }

    @Test
    fun everyPaperValue_carriesItsLine_andNothingIsUnverified() {
        assertTrue(text, text.contains("full text 003_8ca1dc8f53472543.txt"))
        assertLine("""triangle\s+6, "diagonal" \(:107, :171\); cells: Figure 5 only\s+X\.\./XX\./XXX\s+0,3,4,6,7,8""")
        assertLine("""Task 1 trials\s+3 grains x 4 shapes x 3 reps = 36 \(:144, :150\)\s+12 x 3 = 36 \(shaping-compliance\)""")
        assertLine("""breaks, calibration\s+.*break before 2 blocks, calibration before 3""")
        assertLine("""Task 2 trials\s+5 shapes x 39 grains x 3 = 15, random \(:171, :175\)\s+5 x 3 = 15""")
        assertLine("""starting current\s+0\.8 mA, raised gradually \(:152\)\s+0\.81 mA \(step 60\)""")
        for (banned in listOf("not reached", "unverified", "n/t", "not checked")) assertTrue(banned, !text.contains(banned))
    }

    @Test
    fun simulatedFigures_standApartAndSaySo() {
        val simulated = text.indexOf("simulated, not comparable")
        val papers = text.indexOf("the paper's results")
        assertTrue(text, papers in 0 until simulated)
        // The paper's block prints no figure of ours; the simulated block has the analysis' three tables.
        assertTrue(text, !text.substring(papers, simulated).contains("F("))
        assertLine("""grains:electrode\s+F\(9, 549\)""")
        assertLine("""ART ANOVA, number of electrodes \(Figure 4b\): electrodes\s+F\(3, """)
    }
}
