package org.hapticon.sensor.glove

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

class HandshakeCsvTest {
    @Test
    fun readAngles_headerCommentsAndBlanks_parsesTheRows() {
        val text = "# glove A\n time_s , thumb_deg,MIDDLE_DEG \n\n0.0,0,0\n0.01,1.5,2e1\n"
        assertEquals(
            listOf(AngleSample(0.0, 0.0, 0.0), AngleSample(0.01, 1.5, 20.0)),
            HandshakeCsv.readAngles(text),
        )
    }

    @Test
    fun readAngles_wrongHeader_namesLineOne() {
        val e = assertThrows(SensorCsvException::class.java) { HandshakeCsv.readAngles("time,thumb,middle\n0,0,0\n", "a.csv") }
        assertEquals(1, e.lineNumber)
        assertEquals("a.csv:1: expected a header time_s,thumb_deg,middle_deg, got \"time,thumb,middle\"", e.message)
    }

    @Test
    fun readAngles_wrongColumnCount_namesTheLine() {
        val e = assertThrows(SensorCsvException::class.java) { HandshakeCsv.readAngles("time_s,thumb_deg,middle_deg\n0,0,0\n# note\n0.01,5\n", "a.csv") }
        assertEquals("a.csv:4: expected 3 columns (time_s,thumb_deg,middle_deg), got 2", e.message)
    }

    @Test
    fun readAngles_notANumberOrNonFinite_namesTheLineAndColumn() {
        assertEquals(
            "csv:3: middle_deg is not a number: \"ten\"",
            assertThrows(SensorCsvException::class.java) { HandshakeCsv.readAngles("time_s,thumb_deg,middle_deg\n0,0,0\n0.1,0,ten\n") }.message,
        )
        assertEquals(
            "csv:2: thumb_deg must be finite, was NaN",
            assertThrows(SensorCsvException::class.java) { HandshakeCsv.readAngles("time_s,thumb_deg,middle_deg\n0,NaN,0\n") }.message,
        )
    }

    @Test
    fun readAngles_timeNotIncreasing_namesTheLine() {
        val e = assertThrows(SensorCsvException::class.java) { HandshakeCsv.readAngles("time_s,thumb_deg,middle_deg\n0.1,0,0\n0.1,0,0\n") }
        assertEquals("csv:3: time must increase, 0.1 s after 0.1 s", e.message)
    }

    @Test
    fun readAngles_empty_isAMissingHeader() {
        assertEquals(1, assertThrows(SensorCsvException::class.java) { HandshakeCsv.readAngles("\n# only a comment\n") }.lineNumber)
    }

    @Test
    fun commands_partnerHeldBetweenItsSamplesAndOpenBeforeItsFirst() {
        val self = "time_s,thumb_deg,middle_deg\n0.00,50,105\n0.01,50,105\n0.02,50,105\n0.03,50,105\n"
        // The partner's first sample arrives at 0.015 s, between self's 2nd and 3rd.
        val partner = "time_s,thumb_deg,middle_deg\n0.015,0,67.95\n"
        val steps = HandshakeCsv.commands(self, partner)
        assertEquals(listOf(0.0, 0.01, 0.02, 0.03), steps.map { it.timeSeconds })
        // Before it: partner open, palm = (0.085·0.5 + 0.085)·2.87 + 1.23 = 0.1275·2.87 + 1.23.
        assertEquals(1.595925, steps[1].frame.command(HandRegion.PALM).pressureVolts, 1e-12)
        // From it on, held: palm 2.19145 V.
        assertEquals(2.19145, steps[2].frame.command(HandRegion.PALM).pressureVolts, 1e-12)
        assertEquals(2.19145, steps[3].frame.command(HandRegion.PALM).pressureVolts, 1e-12)
    }

    @Test
    fun commands_badPartnerLine_namesThePartnerFile() {
        val e = assertThrows(SensorCsvException::class.java) {
            HandshakeCsv.commands("time_s,thumb_deg,middle_deg\n0,0,0\n", "time_s,thumb_deg,middle_deg\n0,0\n", "a.csv", "b.csv")
        }
        assertEquals("b.csv", e.source)
        assertEquals(2, e.lineNumber)
    }

    @Test
    fun format_oneActiveAndOneRestingStep_isTheDocumentedCsv() {
        val self = "time_s,thumb_deg,middle_deg\n0,50,105\n0.5,0,0\n"
        val partner = "time_s,thumb_deg,middle_deg\n0,0,67.95\n0.5,0,0\n"
        val lines = HandshakeCsv.format(HandshakeCsv.commands(self, partner)).lines()
        assertEquals(
            "time_s,active,thumb_v,thumb_deg,thumb_servo,thumb_amp,index_v,index_deg,index_servo,index_amp," +
                "middle_v,middle_deg,middle_servo,middle_amp,ring_v,ring_deg,ring_servo,ring_amp," +
                "pinky_v,pinky_deg,pinky_servo,pinky_amp,palm_v,palm_deg,palm_amp",
            lines[0],
        )
        assertEquals(
            "0.000000,1,1.9714,120.65,635,177,0.9220,114.00,600,169,1.7288,125.40,660,182," +
                "0.8088,113.05,595,168,1.1081,111.15,585,166,2.1915,103.85,112",
            lines[1],
        )
        assertEquals("0.500000,0" + ",0.0000,0.00,0,0".repeat(5) + ",0.0000,0.00,0", lines[2])
        assertEquals("", lines[3])
        assertTrue(lines.size == 4)
        assertFalse(lines[2].contains("NaN"))
    }
}
