package org.hapticon.gesture.io

import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class RecordingCsvTest {
    @Test fun readsChannelsUnitsAndRateFromTheTimeColumn() {
        val recording = RecordingCsv.read("time_s,force_N,bend\n0.000,1.5,3\n0.010,2.5,4\n0.020,3.5,5\n")
        assertEquals(100.0, recording.sampleRate, 1e-9)
        assertEquals(listOf("force", "bend"), recording.channels.map { it.name })
        assertEquals("N", recording.channel("force")!!.unit)
        assertEquals("", recording.channel("bend")!!.unit)
        assertArrayEquals(doubleArrayOf(1.5, 2.5, 3.5), recording.channel("force")!!.toDoubleArray(), 0.0)
    }

    @Test fun rejectsIrregularTimingNamingTheLine() {
        val e = assertThrows(RecordingFormatException::class.java) {
            RecordingCsv.read("time_s,force_N\n0.00,1\n0.01,1\n0.03,1\n0.04,1\n", "press.csv")
        }
        assertEquals("press.csv:4: irregular timing: step 0.0200000 s from the previous row, the typical (median) step is 0.0100000 s", e.message)
    }

    @Test fun rejectsNanAndBlankCellsByDefault() {
        val nan = assertThrows(RecordingFormatException::class.java) { RecordingCsv.read("time_s,force_N\n0,1\n0.01,NaN\n0.02,1\n", "a.csv") }
        assertEquals("a.csv:3: force_N is NaN; gaps are rejected (fill them, or read with GapPolicy.INTERPOLATE)", nan.message)
        val blank = assertThrows(RecordingFormatException::class.java) { RecordingCsv.read("time_s,force_N\n0,1\n0.01,2\n0.02,\n", "b.csv") }
        assertEquals("b.csv:4: force_N is blank; gaps are rejected (fill them, or read with GapPolicy.INTERPOLATE)", blank.message)
        val text = assertThrows(RecordingFormatException::class.java) { RecordingCsv.read("time_s,force_N\n0,1\n0.01,x\n", "c.csv") }
        assertEquals("c.csv:3: force_N 'x' is not a number", text.message)
    }

    @Test fun interpolatesGapsWhenAsked() {
        val recording = RecordingCsv.read(
            "time_s,force_N\n0,NaN\n0.01,1\n0.02,\n0.03,nan\n0.04,4\n0.05,inf\n",
            gaps = RecordingCsv.GapPolicy.INTERPOLATE,
        )
        assertArrayEquals(doubleArrayOf(1.0, 1.0, 2.0, 3.0, 4.0, 4.0), recording.channels[0].toDoubleArray(), 1e-12)
        val empty = assertThrows(RecordingFormatException::class.java) {
            RecordingCsv.read("time_s,force_N\n0,NaN\n0.01,NaN\n", "d.csv", RecordingCsv.GapPolicy.INTERPOLATE)
        }
        assertEquals("d.csv:1: channel force_N has no finite sample to interpolate from", empty.message)
    }

    @Test fun rejectsBadHeadersAndShortFiles() {
        assertEquals("x.csv: empty file, expected a header time_s,<channel>..", message(""))
        assertEquals("x.csv:1: first column must be time_s, was 't'", message("t,force\n0,1\n1,1\n"))
        assertEquals("x.csv:1: need at least one channel after time_s", message("time_s\n0\n1\n"))
        assertEquals("x.csv:1: duplicate channel names in a,a", message("time_s,a,a\n0,1,1\n1,1,1\n"))
        assertEquals("x.csv:1: need at least 2 rows to know the sample rate, found 1", message("time_s,a\n0,1\n"))
        assertEquals("x.csv:3: expected 2 cells, found 3", message("time_s,a\n0,1\n1,1,1\n"))
        assertEquals("x.csv:3: time_s must increase, 1.0 to 0.0 does not", message("time_s,a\n1,1\n0,1\n"))
    }

    @Test fun writeThenReadGivesTheSameRecording() {
        val original = Recording(250.0, listOf(Channel("force", "N", doubleArrayOf(0.1, -2.5, 1e-9, 3.0)), Channel("x", "", doubleArrayOf(1.0, 2.0, 3.0, 4.0))))
        val text = RecordingCsv.write(original)
        assertEquals("time_s,force_N,x", text.lines().first())
        val back = RecordingCsv.read(text)
        assertEquals(250.0, back.sampleRate, 1e-9)
        assertEquals(listOf("N", ""), back.channels.map { it.unit })
        assertArrayEquals(original.channels[0].toDoubleArray(), back.channels[0].toDoubleArray(), 0.0)
    }

    private fun message(text: String): String? = assertThrows(RecordingFormatException::class.java) { RecordingCsv.read(text, "x.csv") }.message
}
