package org.hapticon.sensor.protocol.framed

import org.hapticon.sensor.protocol.ascii
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotEquals
import org.junit.Test

class Crc16Test {
    @Test
    fun compute_checkString_isCcittFalseCheckValue() {
        // The catalogue check value of CRC-16/CCITT-FALSE (CRC-16/IBM-3740).
        assertEquals(0x29B1, Crc16.compute(ascii("123456789")))
    }

    @Test
    fun compute_nothing_isInitialValue() {
        assertEquals(0xFFFF, Crc16.compute(ByteArray(0)))
    }

    @Test
    fun compute_dataFollowedByItsCrcHighByteFirst_isZero() {
        val data = ascii("123456789") + byteArrayOf(0x29, 0xB1.toByte())
        assertEquals(0, Crc16.compute(data))
    }

    @Test
    fun compute_inPieces_equalsWhole() {
        val data = ascii("Hapticon framed protocol")
        val first = Crc16.compute(data, 0, 10)
        assertEquals(Crc16.compute(data), Crc16.compute(data, 10, data.size - 10, first))
    }

    @Test
    fun compute_singleBitFlips_allChangeTheCrc() {
        val data = ascii("0123456789abcdef")
        val crc = Crc16.compute(data)
        for (bit in 0 until data.size * 8) {
            val flipped = data.copyOf()
            flipped[bit / 8] = (flipped[bit / 8].toInt() xor (1 shl (bit % 8))).toByte()
            assertNotEquals("bit $bit", crc, Crc16.compute(flipped))
        }
    }
}
