package org.hapticon.sensor.protocol

import org.hapticon.sensor.protocol.stream.Decimal
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

class DecimalTest {
    private fun parse(text: String): Double = ascii(text).let { Decimal.parse(it, 0, it.size) }

    @Test
    fun parse_integersAndSigns_exact() {
        assertEquals(0.0, parse("0"), 0.0)
        assertEquals(1023.0, parse("1023"), 0.0)
        assertEquals(-12.0, parse("-12"), 0.0)
        assertEquals(7.0, parse("+7"), 0.0)
        assertEquals(9_007_199_254_740_992.0, parse("9007199254740992"), 0.0)
        assertEquals(1.0 / Double.NEGATIVE_INFINITY, parse("-0"), 0.0) // -0.0
        assertEquals(java.lang.Double.doubleToRawLongBits(-0.0), java.lang.Double.doubleToRawLongBits(parse("-0")))
    }

    @Test
    fun parse_decimalsAndExponents_matchStringToDouble() {
        for (text in listOf("0.1", "3.25", ".5", "5.", "-0.001", "123.456", "1e3", "1E-3", "2.5e+2", "12345678901234567890", "9007199254740993",
            "0.30000000000000004", "1e23", "4.9e-324", "1.7976931348623157e308", "00000000000000000000001.5", "1e-400", "1.7976931348623157e308")) {
            assertEquals(text, text.toDouble(), parse(text), 0.0)
        }
    }

    @Test
    fun parse_manyGeneratedNumbers_matchStringToDoubleBitForBit() {
        var seed = 12345L
        fun next(): Long {
            seed = seed * 6364136223846793005L + 1442695040888963407L
            return seed ushr 17
        }
        repeat(20_000) {
            val digits = (next() % 19).toInt() + 1
            val mantissa = buildString { repeat(digits) { append('0' + (next() % 10).toInt()) } }
            val point = (next() % (digits + 1)).toInt()
            val text = (if (next() % 2 == 0L) "-" else "") + mantissa.substring(0, point) + "." + mantissa.substring(point) +
                (if (next() % 4 == 0L) "e" + ((next() % 60) - 30) else "")
            val expected = java.lang.Double.doubleToRawLongBits(text.toDouble())
            assertEquals(text, expected, java.lang.Double.doubleToRawLongBits(parse(text)))
        }
    }

    @Test
    fun parse_notExactlyOneNumber_isNaN() {
        for (text in listOf("", "-", "+", ".", "-.", "1.2.3", "1e", "1e+", "e5", "nan", "NaN", "inf", "Infinity", "ovf", "0x10", "1d", "1f",
            "1 2", "--1", "+-1", "1,5", " 1", "1 ", "12a", "1e400", "-1e999999999")) {
            assertTrue("'$text'", parse(text).isNaN())
        }
    }

    @Test
    fun parse_subrange_readsOnlyThatRange() {
        val bytes = ascii("xx-42.5yy")
        assertEquals(-42.5, Decimal.parse(bytes, 2, 7), 0.0)
    }
}
