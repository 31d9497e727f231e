package org.hapticon.companion.replicate

import org.hapticon.companion.EXIT_OK
import org.hapticon.companion.EXIT_USAGE
import org.hapticon.companion.cli
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

class ReplicateCommandTest {
    @Test
    fun replicate_withoutId_listsTheReplications() {
        val result = cli("replicate")
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        assertTrue(result.stdout, result.stdout.startsWith("000  Haptic icons (Wei et al.)"))
    }

    @Test
    fun replicate000_printsTable3BesideBothModelsAndTheProcedures() {
        val result = cli("replicate", "000")
        assertEquals(result.toString(), EXIT_OK, result.exitCode)
        val lines = result.stdout.lines()
        assertTrue(result.stdout, lines.contains("stroke  Table 3           1.00000  1.00000  0.300  1.00000      —    349.23   2.600     4"))
        assertTrue(result.stdout, lines.contains("        processing model  1.00000  1.00000  0.300  1.00000  1.000    349.23   2.600     4"))
        // knock as felt: the attack 221 samples (0.00501 s), the sustain one sample short (440 samples, 0.00998 s), the release to the disconnection at 882.
        assertTrue(result.stdout, lines.any { it.startsWith("        processing model  0.00501  0.00998  0.500  0.00501  0.999    220.00   0.270     3") })
        assertTrue(result.stdout, lines.any { it.startsWith("participants     | 16 ") && it.endsWith("| open") })
        assertTrue(result.stdout, lines.any { it.startsWith("masking ") && it.contains("| white ") && it.endsWith("| none") })
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

    @Test
    fun replicate_unknownId_isAOneLineUsageError() {
        val result = cli("replicate", "999")
        assertEquals(EXIT_USAGE, result.exitCode)
        assertEquals(listOf("hapticon: no replication '999'; known: 000"), result.stderrLines)
    }
}
