package org.hapticon.study.compliance

import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.setGrains
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

/**
 * Each study condition as the bytes the board receives when its trial starts: decoded here with a COBS and
 * CRC-16/CCITT-FALSE of the test's own (docs/protocols.md), not the encoder's, field by field.
 */
class ComplianceFirmwareParamsTest {
    private val levels = listOf(60, 61, 62, 63, 64, 65, 66, 67, 200)

    /** Electrode numbers (row by row from the top left) each shape drives on the 3×3 array (docs/sensor-models.md). */
    private val members = mapOf(
        ElectrodeMask.LARGE_SQUARE to listOf(0, 1, 2, 3, 4, 5, 6, 7, 8),
        ElectrodeMask.VERTICAL_LINE to listOf(0, 1, 3, 4, 6, 7),
        ElectrodeMask.HORIZONTAL_LINE to listOf(0, 1, 2, 3, 4, 5),
        ElectrodeMask.SMALL_SQUARE to listOf(0, 1, 3, 4),
        ElectrodeMask.TRIANGLE to listOf(0, 3, 4, 6, 7, 8),
    )

    private class Command(val type: Int, val sequence: Int, val payload: IntArray)

    private fun decode(wire: ByteArray): Command {
        assertEquals("delimiter", 0, wire.last().toInt())
        val frame = ArrayList<Int>()
        var i = 0
        while (i < wire.size - 1) {
            val code = wire[i].toInt() and 0xFF
            for (k in 1 until code) frame += wire[i + k].toInt() and 0xFF
            i += code
            if (code < 0xFF && i < wire.size - 1) frame += 0
        }
        var crc = 0xFFFF
        for (b in frame.dropLast(2)) {
            crc = crc xor (b shl 8)
            repeat(8) { crc = if (crc and 0x8000 != 0) (crc shl 1) xor 0x1021 else crc shl 1 }
            crc = crc and 0xFFFF
        }
        assertEquals("CRC, high byte first", crc, (frame[frame.size - 2] shl 8) or frame.last())
        assertEquals("version", 1, frame[0])
        return Command(frame[1], frame[2] or (frame[3] shl 8), frame.subList(4, frame.size - 2).toIntArray())
    }

    @Test
    fun everyShape_onTheWire_isItsGrainsRangeMembersAndCalibratedSteps() {
        val range = FirmwareForceRange.ofAdcBits(12)
        val encoder = FramedEncoder()
        for ((sequence, condition) in ComplianceStudy.EXTENDED.conditions.withIndex()) {
            val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
            val n = encoder.setGrains(condition.firmwareParams(levels, range), buffer)
            val command = decode(buffer.copyOf(n))
            val p = command.payload
            assertEquals(0x13, command.type)
            assertEquals(sequence, command.sequence)
            assertEquals(21, p.size)
            assertEquals(condition.id, condition.grains, p[0])
            assertEquals("linear", 0, p[1])
            assertEquals("min", 0, p[2] or (p[3] shl 8))
            assertEquals("max: the 12-bit board's full scale", 4095, p[4] or (p[5] shl 8))
            val bits = p[6] or (p[7] shl 8)
            assertEquals(condition.id, members.getValue(condition.mask), (0 until 9).filter { bits and (1 shl it) != 0 })
            assertEquals("every electrode's calibrated step; the board drives the members'", levels, p.slice(8 until 17))
            assertEquals("20 Hz in 0.1 Hz", 200, p[17] or (p[18] shl 8))
            // Dead time = the grain's own delivery, 8 ms + 250 µs per electrode (003_8ca1dc8f53472543.txt:97).
            assertEquals(condition.id, 8000 + 250 * members.getValue(condition.mask).size, p[19] or (p[20] shl 8))
        }
        assertEquals(20, ComplianceStudy.EXTENDED.conditions.size)
    }

    @Test
    fun firmwareParams_limits_capAcceptedJustPastRefused() {
        val condition = ComplianceCondition(39, ElectrodeMask.SMALL_SQUARE)
        assertEquals(List(9) { 200 }, condition.firmwareParams(List(9) { 200 }, FirmwareForceRange.ofAdcBits(10)).steps)
        val refused = assertThrows(SafetyLimitException::class.java) { condition.firmwareParams(List(8) { 200 } + 201, FirmwareForceRange.ofAdcBits(10)) }
        assertEquals("amplitude step must be in 0..200, was 201", refused.message)
        assertThrows(IllegalArgumentException::class.java) { condition.firmwareParams(List(8) { 60 }, FirmwareForceRange.ofAdcBits(10)) }
    }
}
