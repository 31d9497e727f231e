package org.hapticon.sensor.protocol.lucid

import org.hapticon.sensor.protocol.ascii
import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test

class LucidForceFeedbackTest {
    @Test
    fun encode_fiveValues_alphaCommandLine() {
        assertArrayEquals(ascii("A0B250C500D750E1000\n"), LucidForceFeedback.encode(intArrayOf(0, 250, 500, 750, 1000)))
    }

    @Test
    fun encode_allAtMaximum_isMaxLength() {
        val buffer = ByteArray(40) { '#'.code.toByte() }
        assertEquals(LucidForceFeedback.MAX_LENGTH, LucidForceFeedback.encode(intArrayOf(1000, 1000, 1000, 1000, 1000), buffer, 3))
        assertEquals("###A1000B1000C1000D1000E1000\n###########", String(buffer, Charsets.US_ASCII))
    }

    @Test
    fun encode_valueOutsideServoRange_refusedAndNothingWritten() {
        for (bad in listOf(-1, 1001, Int.MIN_VALUE)) {
            val buffer = ByteArray(LucidForceFeedback.MAX_LENGTH)
            try {
                LucidForceFeedback.encode(intArrayOf(0, 0, bad, 0, 0), buffer)
                fail("accepted $bad")
            } catch (e: SafetyLimitException) {
                assertEquals("servo", e.limit)
            }
            assertArrayEquals(ByteArray(LucidForceFeedback.MAX_LENGTH), buffer)
        }
    }

    @Test(expected = IllegalArgumentException::class)
    fun encode_fourValues_throws() {
        LucidForceFeedback.encode(intArrayOf(1, 2, 3, 4))
    }

    @Test(expected = IndexOutOfBoundsException::class)
    fun encode_destinationTooSmall_throws() {
        LucidForceFeedback.encode(intArrayOf(1, 2, 3, 4, 5), ByteArray(LucidForceFeedback.MAX_LENGTH - 1))
    }

    @Test
    fun encode_decodedByTheFirmwaresArgumentRule_givesTheValues() {
        // The glove firmware takes atoi() after each of the letters A..E.
        val line = String(LucidForceFeedback.encode(intArrayOf(7, 80, 900, 1000, 0)), Charsets.US_ASCII)
        val values = "ABCDE".map { key -> line.substring(line.indexOf(key) + 1).takeWhile(Char::isDigit).toInt() }
        assertEquals(listOf(7, 80, 900, 1000, 0), values)
    }
}
