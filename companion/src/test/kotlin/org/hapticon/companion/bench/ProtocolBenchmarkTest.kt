package org.hapticon.companion.bench

import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

/** Runs the benchmark small: not for speed (benchmarks measure that), but for what it reports. */
class ProtocolBenchmarkTest {
    @Test
    fun run_smallBuffers_reportsEachProtocolWithoutPerFrameAllocation() {
        val results = ProtocolBenchmark.run(bufferBytes = 1 shl 20, runs = 2, warmupRuns = 2, readSize = 4096)
        assertEquals(listOf("csv", "framed", "lucidgloves"), results.map { it.name })
        for (r in results) {
            assertTrue(r.toString(), r.bytes >= 1 shl 20)
            assertTrue(r.toString(), r.frames > 10_000)
            assertTrue(r.toString(), r.megabytesPerSecond > 0 && r.framesPerSecond > 0)
            // Any allocation per frame would be at least 16 bytes (an object header); the measurement
            // itself costs a few bytes over tens of thousands of frames.
            assertTrue(r.toString(), r.bytesAllocatedPerFrame < 1.0)
        }
    }

    @Test(expected = IllegalArgumentException::class)
    fun run_tinyBuffer_throws() {
        ProtocolBenchmark.run(bufferBytes = 100)
    }
}
