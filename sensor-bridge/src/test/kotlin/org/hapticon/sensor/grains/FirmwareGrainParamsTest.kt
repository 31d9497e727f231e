package org.hapticon.sensor.grains

import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.electrotactile.ElectrodePattern
import org.hapticon.sensor.protocol.framed.Cobs
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test

class FirmwareGrainParamsTest {
    private val smallSquareAtCap = FirmwareGrainParams(9, BinDistribution.LINEAR, 0, 1000, ElectrodeMask.SMALL_SQUARE.pattern, listOf(200, 200, 0, 200, 200, 0, 0, 0, 0))

    private fun bytes(vararg values: Int) = ByteArray(values.size) { values[it].toByte() }

    @Test
    fun payload_isTheBytesTheFirmwareSketchTestSends() {
        // sensor-bridge/firmware/test/sketch_test.cpp sends exactly these 21 bytes and expects 9 grains on electrodes 0, 1, 3, 4.
        assertArrayEquals(
            bytes(9, 0, 0x00, 0x00, 0xe8, 0x03, 0x1b, 0x00, 200, 200, 0, 200, 200, 0, 0, 0, 0, 0xc8, 0x00, 0x28, 0x23),
            smallSquareAtCap.payload(),
        )
    }

    @Test
    fun grainMicros_defaultsToTheGrainsOwnDelivery_asTheBoardsDeadTime() {
        // No grain while one is being delivered (003_8ca1dc8f53472543.txt:97): 8 ms to the second pulse + 250 µs per electrode.
        val range = FirmwareForceRange(0, 1023)
        val expected = mapOf(ElectrodeMask.SMALL_SQUARE to 9000, ElectrodeMask.HORIZONTAL_LINE to 9500, ElectrodeMask.VERTICAL_LINE to 9500, ElectrodeMask.TRIANGLE to 9500, ElectrodeMask.LARGE_SQUARE to 10250)
        for ((mask, micros) in expected) {
            assertEquals(mask.name, micros, FirmwareGrainParams.of(19, BinDistribution.LINEAR, range, mask.pattern, List(9) { 60 }).grainMicros)
        }
        // The Kotlin twin holds the same grains back: 10.25 ms at 1 kHz is 11 samples, so the next grain's sample is after the last pulse.
        val large = FirmwareGrainParams.of(19, BinDistribution.LINEAR, range, ElectrodeMask.LARGE_SQUARE.pattern, List(9) { 60 })
        assertEquals(11, GrainDecider(large.deciderSettings(), 1000.0).grainSamples)
    }

    @Test
    fun setGrains_frame_isTypeOx13WithThePayload() {
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val n = FramedEncoder(11).setGrains(smallSquareAtCap, buffer)
        val frame = Cobs.decode(buffer.copyOf(n - 1))!!
        // version 1, SET_GRAINS, sequence 11 (LE), 21 payload bytes, 2 CRC bytes.
        assertEquals(4 + 21 + 2, frame.size)
        assertArrayEquals(bytes(0x01, 0x13, 0x0b, 0x00), frame.copyOf(4))
        assertArrayEquals(smallSquareAtCap.payload(), frame.copyOfRange(4, 25))
    }

    @Test
    fun params_stepAtCapAccepted_justPastRefused() {
        smallSquareAtCap.copy(steps = List(9) { 200 })
        try {
            smallSquareAtCap.copy(steps = List(8) { 200 } + 201)
            fail("accepted")
        } catch (e: SafetyLimitException) {
            assertEquals("electrotactileCurrent", e.limit)
        }
    }

    @Test
    fun params_fewerThanFourElectrodesOrBadCounts_areRefused() {
        for (make in listOf(
            { smallSquareAtCap.copy(pattern = ElectrodePattern.of("XXX", "...", "...")) },
            { smallSquareAtCap.copy(grainCount = 100) },
            { smallSquareAtCap.copy(grainCount = -1) },
            { smallSquareAtCap.copy(minForce = 1000) },
            { smallSquareAtCap.copy(cutoffHz = Double.NaN) },
            { smallSquareAtCap.copy(grainMicros = 8999) },
        )) {
            try {
                make()
                fail("accepted")
            } catch (_: IllegalArgumentException) {
            }
        }
    }
}
