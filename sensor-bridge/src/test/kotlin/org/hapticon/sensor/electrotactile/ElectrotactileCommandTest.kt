package org.hapticon.sensor.electrotactile

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class ElectrotactileCommandTest {
    private val full = ElectrotactileUserLimit(2.7)

    @Test
    fun masks_areTheDocumentedPatterns() {
        assertEquals(listOf("XXX", "XXX", "XXX"), ElectrodeMask.LARGE_SQUARE.pattern.rows())
        assertEquals(listOf("XX.", "XX.", "..."), ElectrodeMask.SMALL_SQUARE.pattern.rows())
        assertEquals(listOf("XXX", "XXX", "..."), ElectrodeMask.HORIZONTAL_LINE.pattern.rows())
        assertEquals(listOf("XX.", "XX.", "XX."), ElectrodeMask.VERTICAL_LINE.pattern.rows())
        assertEquals(listOf("X..", "XX.", "XXX"), ElectrodeMask.TRIANGLE.pattern.rows())
        // Shaping Compliance (003_8ca1dc8f53472543.txt:107, :144): large square 9, small square 4, lines 6, triangle 6.
        assertEquals(listOf(9, 4, 6, 6, 6), ElectrodeMask.entries.map { it.pattern.activeCount })
    }

    @Test
    fun masks_members_areTheElectrodeIndicesInScanOrder() {
        assertEquals((0..8).toList(), ElectrodeMask.LARGE_SQUARE.pattern.electrodes())
        assertEquals(listOf(0, 1, 3, 4), ElectrodeMask.SMALL_SQUARE.pattern.electrodes())
        assertEquals(listOf(0, 1, 2, 3, 4, 5), ElectrodeMask.HORIZONTAL_LINE.pattern.electrodes())
        assertEquals(listOf(0, 1, 3, 4, 6, 7), ElectrodeMask.VERTICAL_LINE.pattern.electrodes())
        assertEquals(listOf(0, 3, 4, 6, 7, 8), ElectrodeMask.TRIANGLE.pattern.electrodes())
        assertTrue(ElectrodeMask.entries.all { it.pattern.isStrongEnoughForCompliance })
    }

    @Test
    fun pattern_fewerThanFourElectrodes_isFlaggedTooWeak() {
        assertFalse(ElectrodePattern.of(".X.", ".X.", ".X.").isStrongEnoughForCompliance)
        assertFalse(ElectrodePattern.of("X..", "...", "...").isStrongEnoughForCompliance)
        assertTrue(ElectrodePattern.of("X.X", "...", "X.X").isStrongEnoughForCompliance)
    }

    @Test
    fun pattern_bits_areRowMajorFromTheTopLeft() {
        // Electrode 3·row + column: the top two rows are bits 0..5 = 0b000111111 = 63.
        assertEquals(63, ElectrodeMask.HORIZONTAL_LINE.pattern.bits)
        assertEquals(0b011011011, ElectrodeMask.VERTICAL_LINE.pattern.bits)
        assertTrue(ElectrodeMask.TRIANGLE.pattern.isOn(1, 1))
        assertFalse(ElectrodeMask.TRIANGLE.pattern.isOn(0, 1))
        assertEquals(0b111011001, ElectrodeMask.TRIANGLE.pattern.bits)
        assertEquals("X../XX./XXX", ElectrodeMask.TRIANGLE.pattern.toString())
    }

    @Test
    fun pattern_emptyMalformedOrOutOfRange_isRejected() {
        for (make in listOf(
            { ElectrodePattern(0) },
            { ElectrodePattern(512) },
            { ElectrodePattern.of("...", "...", "...") },
            { ElectrodePattern.of("XX", "XXX", "XXX") },
            { ElectrodePattern.of("XXX", "XOX", "XXX") },
            { ElectrodePattern.of("XXX", "XXX") },
            { ElectrodeMask.TRIANGLE.pattern.isOn(3, 0) },
        )) {
            try {
                make()
                fail("accepted")
            } catch (_: IllegalArgumentException) {
            }
        }
    }

    @Test
    fun grainPulseTrain_isTwoAnodic200MicrosecondPulsesAt125Hz() {
        val grain = PulseTrain.GRAIN
        assertEquals(PulseTrain(125.0, 2, 200.0, PulsePolarity.ANODIC), grain)
        // 1/125 s between onsets plus one width: 8.2 ms.
        assertEquals(0.0082, grain.durationSeconds, 1e-15)
    }

    @Test
    fun command_atTheHardCap_isAcceptedWithItsCharge() {
        val command = ElectrotactileCommand(ElectrodeMask.LARGE_SQUARE.pattern, 2.7, full)
        // 2.7 mA × 200 µs = 0.54 µC.
        assertEquals(0.54, command.chargePerPulseMicrocoulombs, 1e-15)
    }

    @Test
    fun command_justAboveTheHardCap_isRefused() {
        assertCurrentRefused { ElectrotactileCommand(ElectrodeMask.LARGE_SQUARE.pattern, Math.nextUp(2.7), full) }
        assertCurrentRefused { ElectrotactileUserLimit(Math.nextUp(2.7)) }
        assertCurrentRefused { ElectrotactileUserLimit(3.0) }
    }

    @Test
    fun command_atAndJustAboveTheUserMaximum_isAcceptedThenRefused() {
        val user = ElectrotactileUserLimit(1.5)
        ElectrotactileCommand(ElectrodeMask.TRIANGLE.pattern, 1.5, user)
        assertCurrentRefused { ElectrotactileCommand(ElectrodeMask.TRIANGLE.pattern, Math.nextUp(1.5), user) }
    }

    @Test
    fun command_copyAboveTheLimit_isRefusedToo() {
        val command = ElectrotactileCommand(ElectrodeMask.TRIANGLE.pattern, 1.0, ElectrotactileUserLimit(1.5))
        assertCurrentRefused { command.copy(currentMilliamps = 2.0) }
        assertCurrentRefused { command.copy(userLimit = ElectrotactileUserLimit(0.5)) }
    }

    @Test
    fun command_zeroNegativeNanOrInfiniteCurrent_isRefused() {
        for (bad in listOf(0.0, -1.0, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY)) {
            assertCurrentRefused { ElectrotactileCommand(ElectrodeMask.VERTICAL_LINE.pattern, bad, full) }
            assertCurrentRefused { ElectrotactileUserLimit(bad) }
        }
    }

    @Test
    fun pulseTrain_aPulseLongerThanItsPeriodOrOutOfRange_isRejected() {
        for (make in listOf(
            { PulseTrain(frequencyHz = 1000.0, pulseWidthMicros = 1000.0) },
            { PulseTrain(frequencyHz = 0.5) },
            { PulseTrain(pulseCount = 0) },
            { PulseTrain(pulseWidthMicros = Double.NaN) },
        )) {
            try {
                make()
                fail("accepted")
            } catch (_: IllegalArgumentException) {
            }
        }
    }
}
