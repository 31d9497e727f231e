package org.hapticon.sensor.protocol.stream

/**
 * Parses ASCII decimal numbers (`-12`, `3.25`, `.5`, `1e3`) from bytes without allocating, with the
 * same result as [String.toDouble] (correctly rounded). Numbers too large for a double are refused,
 * not turned into infinity: no sensor reads 1e400.
 */
internal object Decimal {
    // 10^0..10^22 are exact doubles; a mantissa below 2^53 is exact too, so one multiplication or
    // division by them is correctly rounded (Clinger's fast path). Everything else takes the slow path.
    private val POWERS_OF_TEN = DoubleArray(23).also { p ->
        p[0] = 1.0
        for (i in 1 until p.size) p[i] = p[i - 1] * 10.0
    }
    private const val MAX_EXACT_MANTISSA = 1L shl 53
    private const val MANTISSA_LIMIT = (Long.MAX_VALUE - 9) / 10

    /** The number in [start] until [end] of [bytes], or NaN if that is not exactly one finite number. */
    fun parse(bytes: ByteArray, start: Int, end: Int): Double {
        var i = start
        var negative = false
        if (i < end && (bytes[i] == MINUS || bytes[i] == PLUS)) {
            negative = bytes[i] == MINUS
            i++
        }
        var mantissa = 0L
        var digits = 0
        var exponent = 0
        var overflow = false
        while (i < end) {
            val d = bytes[i] - ZERO
            if (d !in 0..9) break
            if (mantissa <= MANTISSA_LIMIT) mantissa = mantissa * 10 + d else { overflow = true; exponent++ }
            digits++
            i++
        }
        if (i < end && bytes[i] == DOT) {
            i++
            while (i < end) {
                val d = bytes[i] - ZERO
                if (d !in 0..9) break
                if (mantissa <= MANTISSA_LIMIT) { mantissa = mantissa * 10 + d; exponent-- } else overflow = true
                digits++
                i++
            }
        }
        if (digits == 0) return Double.NaN
        if (i < end && (bytes[i] == LOWER_E || bytes[i] == UPPER_E)) {
            i++
            var exponentNegative = false
            if (i < end && (bytes[i] == MINUS || bytes[i] == PLUS)) {
                exponentNegative = bytes[i] == MINUS
                i++
            }
            var written = 0
            var value = 0
            while (i < end) {
                val d = bytes[i] - ZERO
                if (d !in 0..9) break
                if (value < 100_000) value = value * 10 + d
                written++
                i++
            }
            if (written == 0) return Double.NaN
            exponent += if (exponentNegative) -value else value
        }
        if (i != end) return Double.NaN
        if (!overflow && mantissa < MAX_EXACT_MANTISSA && exponent in -22..22) {
            val magnitude = if (exponent >= 0) mantissa * POWERS_OF_TEN[exponent] else mantissa / POWERS_OF_TEN[-exponent]
            return if (negative) -magnitude else magnitude
        }
        // Rare (long or extreme numbers): the grammar above has been checked, so the JDK parser
        // sees only [sign]digits[.digits][e[sign]digits] and none of the forms it also accepts
        // ("NaN", "0x1p3", "1d").
        val value = String(bytes, start, end - start, Charsets.ISO_8859_1).toDouble()
        return if (value.isInfinite()) Double.NaN else value
    }

    private const val ZERO: Byte = '0'.code.toByte()
    private const val MINUS: Byte = '-'.code.toByte()
    private const val PLUS: Byte = '+'.code.toByte()
    private const val DOT: Byte = '.'.code.toByte()
    private const val LOWER_E: Byte = 'e'.code.toByte()
    private const val UPPER_E: Byte = 'E'.code.toByte()
}
