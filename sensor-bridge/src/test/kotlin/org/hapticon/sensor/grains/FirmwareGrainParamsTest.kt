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
            bytes(9, 0, 0x00, 0x00, 0xe8, 0x03, 0x1b, 0x00, 200, 200, 0, 200, 200, 0, 0, 0, 0, 0xc8, 0x00, 0x20, 0x4e),
            smallSquareAtCap.payload(),
        )
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
