package org.hapticon.companion.replicate

import org.hapticon.companion.EXIT_OK
import org.hapticon.companion.cli
import org.hapticon.sensor.glove.AdcScale
import org.hapticon.sensor.glove.FlexDivider
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import kotlin.math.abs

class HandshakeReplicationTest {
    private val out: ReplicationOutput by lazy {
        val result = cli("replicate", "handshake")
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        ReplicationOutput(result.stdout)
    }

    @Test
    fun rules_quoteThePapers22Ohms_andStateOurs() {
        assertTrue(out.text, out.text.startsWith("002 Tele-handshake glove"))
        assertTrue(out.text, out.text.contains("paper text: 002_12aacdd60a14fec1.txt, cited as 002:LINE"))
        val divider = out.row("divider fixed resistor")
        assertEquals(listOf("22 Ω", "002:62", "33 kΩ"), divider.subList(1, 4))
        assertTrue(divider[4], divider[4].startsWith("different: 22 Ω leaves ~5 mV of swing"))
        assertEquals(listOf("0, 30, 50, 70, 90°", "002:77", "0, 30, 50, 70, 90°", "same"), out.row("calibration poses").drop(1))
        assertTrue(out.row("pressure -> motor angle table")[1].contains("values only in Figure 10"))
    }

    @Test
    fun startRule_ownMiddleFinger_partnerAloneStartsNothing() {
        val start = out.row("handshake start")
        assertEquals("002:138, 169-170", start[2])
        assertTrue(start[3], start[3].contains("own 30.9° -> palm rest; own 31° -> "))
        assertEquals(0.0, HandshakeCalibrationReplication.palmAfterOneStep(30.9, 60.0, 90.0), 0.0)
        assertTrue(HandshakeCalibrationReplication.palmAfterOneStep(31.0, 60.0, 90.0) > 1.23)
    }

    @Test
    fun swing_22Ohms_isAboutOneTenBitCount_33Kiloohms_353() {
        val printed = HandshakeCalibrationReplication.swing(FlexDivider.PAPER_PRINTED_FIXED_KILOOHMS)
        assertEquals(0.0051822, printed.volts, 1e-7)
        assertEquals(1.06, printed.counts(AdcScale.TEN_BIT), 0.005)
        assertEquals(353.15, HandshakeCalibrationReplication.swing(FlexDivider.DEFAULT_FIXED_KILOOHMS).counts(AdcScale.TEN_BIT), 0.01)
        // Rfix, source, Vout 0°, Vout 90°, swing, 10-bit counts, 12-bit counts, ° per 10-bit count.
        assertEquals(listOf("22 Ω", "paper as printed, 002:62", "4.9932 V", "4.9984 V", "5.2 mV", "1.1", "4.2", "84.88"), out.row("22 Ω"))
        assertEquals(listOf("2.1182 V", "3.7811 V", "1663.0 mV", "340.2"), out.row("22 kΩ").subList(2, 6))
        assertEquals(listOf("1726.1 mV", "353.2", "1413.6", "0.25"), out.row("33 kΩ").drop(4))
    }

    @Test
    fun table1_meanAndSdRecomputedFromItsRows_roundToThePrintedOnes() {
        val t = HandshakeCalibrationReplication.TABLE_1
        val columns = listOf(t.map { it.thumbAlpha }, t.map { it.thumbBeta }, t.map { it.middleAlpha }, t.map { it.middleBeta })
        val halfUnit = listOf(0.0005, 0.005, 0.0005, 0.005)
        for (c in columns.indices) {
            val (mean, sd) = HandshakeCalibrationReplication.meanAndSd(columns[c])
            assertTrue("column $c mean $mean", abs(mean - HandshakeCalibrationReplication.TABLE_1_MEAN[c]) <= halfUnit[c] + 1e-12)
            assertTrue("column $c sd $sd", abs(sd - HandshakeCalibrationReplication.TABLE_1_SD[c]) <= halfUnit[c] + 1e-12)
        }
        assertEquals(listOf("F", "0.027", "8.88", "0.021", "12.65"), out.row("F"))
        assertEquals(listOf("recomputed mean", "0.0157", "16.168", "0.0185", "16.238"), out.row("recomputed mean"))
        assertEquals(listOf("recomputed SD (÷n)", "0.0051", "3.614", "0.0030", "3.461"), out.row("recomputed SD (÷n)"))
    }

    @Test
    fun regions_tables2to5_allSame() {
        val from = out.indexOf("Tables 2-5")
        for (region in listOf("thumb", "index", "middle", "ring", "pinky", "palm")) assertEquals(region, "same", out.row(region, from).last())
        assertEquals(listOf("palm", "1.23, 4.10, 0.17, 0.83", "002:282, 286", "1.23, 4.10, 0.17, 0.83", "same"), out.row("palm", from))
    }

    @Test
    fun faceToFaceProtocol_phasesDurationsAndParticipants_areCited() {
        val roles = out.row("roles")
        assertTrue(roles[1], roles[1].startsWith("9 male participants in their 20s: 6 lead, 3 following"))
        assertEquals("002:147, 152", roles[2])
        assertTrue(out.row("Both Weak")[1].contains("10 s"))
        assertTrue(out.row("Pre-Strong")[1].contains("5 s"))
        assertTrue(out.row("between phases")[1].contains("5 s interval"))
        assertTrue(out.text, out.text.contains("min 30.9° = θM0."))
    }

    @Test
    fun simulation_isItsOwnTable_labelledNotComparable() {
        val heading = out.indexOf("SIMULATED, not comparable with the paper's figures: 500 calibrations")
        assertEquals(listOf("takes per pose", "RMS error of α", "RMS error of β"), out.cells(out.lines[heading + 1]))
        assertTrue(heading > out.indexOf("The face-to-face measurement"))
    }

    @Test
    fun twoTakes_lowerTheFitErrorByAboutRootTwo() {
        val (alpha1, beta1) = HandshakeCalibrationReplication.rmsErrors(1)
        val (alpha2, beta2) = HandshakeCalibrationReplication.rmsErrors(2)
        // Averaging two independent pose errors halves their variance: errors fall by ≈ √2 (1.3..1.6 over 500 trials).
        assertTrue("$alpha1 vs $alpha2", alpha1 / alpha2 in 1.3..1.6)
        assertTrue("$beta1 vs $beta2", beta1 / beta2 in 1.3..1.6)
    }
}
