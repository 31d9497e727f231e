package org.hapticon.sensor.grains

import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

class SensorModelBenchmarkTest {
    @Test
    fun run_shortBudget_reportsBothCasesWithoutAllocatingPerSample() {
        val results = SensorModelBenchmark.run(warmupMillis = 50, measureMillis = 0)
        assertEquals(listOf("grainDecider", "handshakePressure"), results.map { it.name })
        for (result in results) {
            assertEquals(SensorModelBenchmark.MIN_RUNS, result.runs)
            assertEquals(65_536, result.samplesPerRun)
            assertTrue(result.bestNanosPerSample > 0.0)
            assertTrue(result.medianNanosPerSample >= result.bestNanosPerSample)
            // The hot paths use primitive fields and preallocated arrays only.
            assertEquals(result.name, 0.0, result.allocatedBytesPerSample, 0.0)
        }
    }

    @Test
    fun run_negativeBudget_isRejected() {
        try {
            SensorModelBenchmark.run(warmupMillis = -1)
            org.junit.Assert.fail("accepted")
        } catch (_: IllegalArgumentException) {
        }
    }
}
