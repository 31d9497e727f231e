package org.hapticon.sensor.protocol.framed

import org.hapticon.sensor.protocol.ModuleFiles
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assume.assumeTrue
import org.junit.Test

/**
 * Builds the reference firmware's protocol code and sketch with the host's g++ and runs their tests
 * (sensor-bridge/firmware/test/run.sh, grains_test included), so `./build test` covers the C++ side and its agreement with
 * the shared vectors. Skipped where there is no g++.
 */
class FirmwareHostTest {
    @Test
    fun firmwareHostTests_withSharedVectors_pass() {
        assumeTrue("g++ is not installed", ModuleFiles.onPath("g++"))
        val script = ModuleFiles.sensorBridge("firmware/test/run.sh")
        val vectors = ModuleFiles.testFixtures("src/main/resources/streams/framed-vectors.txt")
        val (exit, output) = ModuleFiles.run("bash", script.path, vectors.path)
        assertEquals(output, 0, exit)
        assertTrue(output, Regex("""host_test: \d+ checks, 0 failed""").containsMatchIn(output))
        assertTrue(output, output.contains("shared vectors: 13 frames, 11 exchanges"))
        assertTrue(output, Regex("""grains_test: \d+ checks, 0 failed""").containsMatchIn(output))
        // 9 grains × 2 pulses × the small square's 4 electrodes after SET_GRAINS; then one 200 ms STIMULATE (25 pulses at 125 Hz).
        assertTrue(output, output.contains("sketch_test: 1 infos, 11 samples, 1 acks, 72 grain pulses, 25 stimulus pulses, 0 failed"))
    }
}
