package org.hapticon.sensor.protocol.framed

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Test

class CobsTest {
    private fun bytes(vararg values: Int) = ByteArray(values.size) { values[it].toByte() }
    private fun range(from: Int, to: Int) = ByteArray(to - from + 1) { (from + it).toByte() }

    private fun encode(data: ByteArray): ByteArray {
        val out = ByteArray(Cobs.maxEncodedLength(data.size))
        return out.copyOf(Cobs.encode(data, 0, data.size, out, 0))
    }

    @Test
    fun encode_wikipediaExamples_canonicalBytes() {
        assertArrayEquals(bytes(0x01, 0x01), encode(bytes(0x00)))
        assertArrayEquals(bytes(0x01, 0x01, 0x01), encode(bytes(0x00, 0x00)))
        assertArrayEquals(bytes(0x01, 0x02, 0x11, 0x01), encode(bytes(0x00, 0x11, 0x00)))
        assertArrayEquals(bytes(0x03, 0x11, 0x22, 0x02, 0x33), encode(bytes(0x11, 0x22, 0x00, 0x33)))
        assertArrayEquals(bytes(0x05, 0x11, 0x22, 0x33, 0x44), encode(bytes(0x11, 0x22, 0x33, 0x44)))
        assertArrayEquals(bytes(0x02, 0x11, 0x01, 0x01, 0x01), encode(bytes(0x11, 0x00, 0x00, 0x00)))
        assertArrayEquals(bytes(0xFF) + range(1, 254), encode(range(1, 254)))
        assertArrayEquals(bytes(0x01, 0xFF) + range(1, 254), encode(range(0, 254)))
        assertArrayEquals(bytes(0xFF) + range(1, 254) + bytes(0x02, 0xFF), encode(range(1, 255)))
        assertArrayEquals(bytes(0xFF) + range(2, 255) + bytes(0x01, 0x01), encode(range(2, 255) + bytes(0x00)))
        assertArrayEquals(bytes(0xFE) + range(3, 255) + bytes(0x02, 0x01), encode(range(3, 255) + bytes(0x00, 0x01)))
    }

    @Test
    fun encode_empty_isOneCodeByte() {
        assertArrayEquals(bytes(0x01), encode(ByteArray(0)))
    }

    @Test
    fun encodeThenDecode_everyLengthUpTo600_roundTripsWithoutZeros() {
        for (length in 0..600) {
            val data = ByteArray(length) { if ((it * 7 + length) % 5 == 0) 0 else (it * 31 + 1).toByte() }
            val encoded = encode(data)
            assertFalse("length $length", encoded.any { it.toInt() == 0 })
            assertTrue("length $length", encoded.size <= Cobs.maxEncodedLength(length))
            assertArrayEquals("length $length", data, Cobs.decode(encoded))
        }
    }

    @Test
    fun decode_codeRunningPastTheEnd_isNull() {
        assertNull(Cobs.decode(bytes(0x05, 0x11, 0x22)))
        assertNull(Cobs.decode(bytes(0x02, 0x00)))
        assertEquals(0, Cobs.decode(bytes(0x01))!!.size)
    }
}
