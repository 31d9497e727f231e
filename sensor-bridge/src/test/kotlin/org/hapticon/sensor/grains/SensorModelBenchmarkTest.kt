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
            // The hot paths use primitive fields and preallocated arrays only: an object per sample would cost at
            // least 16 bytes per sample. Below one byte allows only a one-off allocation in the whole run (a JIT
            // tier change briefly running unoptimised code, seen under load as 0.0029 bytes per sample).
            assertTrue("${result.name}: ${result.allocatedBytesPerSample} bytes per sample", result.allocatedBytesPerSample < 1.0)
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
