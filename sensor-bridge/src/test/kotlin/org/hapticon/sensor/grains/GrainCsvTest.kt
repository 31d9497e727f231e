package org.hapticon.sensor.grains

import org.hapticon.sensor.glove.SensorCsvException
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test
import kotlin.math.PI
import kotlin.math.ln

class GrainCsvTest {
    /** Coefficient 1/2 at 1 kHz, 9 grains = ten 1 N bins, 3-sample grains: see GrainDeciderTest. */
    private val settings = GrainSettings(grainCount = 9, maxNewtons = 10.0, cutoffHz = 1000.0 * ln(2.0) / (2 * PI), grainSeconds = 0.003)

    @Test
    fun onsets_forceCsv_givesTheTimesOfTheGrainSamples() {
        val csv = "time_s,force\n" + (0..7).joinToString("\n") { "${it / 1000.0},${if (it == 0) 0.0 else 4.4}" }
        val result = GrainCsv.onsets(csv, settings)
        assertEquals(listOf(0.001, 0.004), result.onsetTimesSeconds)
        // (8 − 1)/0.007 s.
        assertEquals(1000.0, result.sampleRateHz, 1e-9)
        assertEquals(8, result.samples)
        assertEquals(3, result.grainSamples)
    }

    @Test
    fun format_onsets_isOneTimePerLine() {
        val grains = listOf(GrainOnset(0.001, 2, 2.5), GrainOnset(0.004, 4, 4.6875))
        assertEquals("onset_s\n0.001000\n0.004000\n", GrainCsv.format(GrainOnsets(grains, 1000.0, 8, 3)))
        assertEquals("onset_s\n", GrainCsv.format(GrainOnsets(emptyList(), 1000.0, 8, 3)))
    }

    @Test
    fun onsets_voltageCsv_convertsThroughTheFsrDivider() {
        // 4 V is 5 N (400 µS): filtered 2.5, 3.75, 4.375, 4.6875 → bins 2, 3, 4, 4: grains at samples 1 and 4.
        val csv = "# FSR on A0\ntime_s,voltage\n" + (0..7).joinToString("\n") { "${it / 1000.0},${if (it == 0) 0.0 else 4.0}" }
        val grains = GrainCsv.onsets(csv, settings).grains
        assertEquals(listOf(0.001, 0.004), grains.map { it.timeSeconds })
        assertEquals(listOf(2, 4), grains.map { it.bin })
        assertEquals(listOf(2.5, 4.6875), grains.map { it.filteredNewtons })
    }

    @Test
    fun onsets_givenSampleRate_overridesTheEstimate() {
        val csv = "time_s,force\n0,0\n1,4.4\n"
        val result = GrainCsv.onsets(csv, settings, sampleRateHz = 1000.0)
        assertEquals(1000.0, result.sampleRateHz, 0.0)
        assertEquals(listOf(1.0), result.onsetTimesSeconds)
    }

    @Test
    fun onsets_voltageAtTheSupply_isAnErrorNamingTheLine() {
        val e = assertThrows(SensorCsvException::class.java) { GrainCsv.onsets("time_s,voltage\n0,1.0\n0.001,5.0\n", settings, source = "press.csv") }
        assertEquals("press.csv:3: FSR fault SHORTED at 5.0 V", e.message)
    }

    @Test
    fun onsets_badLines_areErrorsNamingTheLine() {
        assertEquals(
            "csv:3: expected 2 columns (time_s,force), got 3",
            assertThrows(SensorCsvException::class.java) { GrainCsv.onsets("time_s,force\n0,0\n0.001,1,2\n", settings) }.message,
        )
        assertEquals(
            "csv:2: force is not a number: \"heavy\"",
            assertThrows(SensorCsvException::class.java) { GrainCsv.onsets("time_s,force\n0,heavy\n", settings) }.message,
        )
        assertEquals(
            "csv:1: expected a header time_s,force or time_s,voltage, got \"t,f\"",
            assertThrows(SensorCsvException::class.java) { GrainCsv.onsets("t,f\n0,0\n", settings) }.message,
        )
    }

    @Test
    fun onsets_oneRowWithoutARate_cannotEstimateIt() {
        assertEquals(
            "csv:2: need at least 2 samples to estimate the sample rate, got 1",
            assertThrows(SensorCsvException::class.java) { GrainCsv.onsets("time_s,force\n0,0\n", settings) }.message,
        )
    }
}
