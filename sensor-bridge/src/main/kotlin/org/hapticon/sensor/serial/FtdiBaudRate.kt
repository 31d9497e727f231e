package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import kotlin.math.abs

/**
 * The FTDI baud-rate divisor (FTDI AN232B-05): the chip divides 3 MHz by n + k/8, with n = 0 and
 * n = 1 reserved for 3 and 2 Mbaud. n goes in wValue bits 0..13; the eighths k are encoded in three
 * bits spread over wValue bits 14..15 and bit 0 of the index's divisor byte.
 *
 * @property value wValue of SET_BAUD_RATE.
 * @property indexBit the third sub-divisor bit, placed in wIndex by the port.
 * @property actualBaudRate the rate the chip will really run at.
 */
internal data class FtdiBaudDivisor(val value: Int, val indexBit: Int, val actualBaudRate: Int)

/** 3 MHz in eighths: the divisor is counted in eighths of the 3 MHz base clock. */
private const val BASE_CLOCK_EIGHTHS = 24_000_000L

/** Sub-divisor eighths 0..7 to the chip's 3-bit code (0, 1/8, 1/4, 3/8, 1/2, 5/8, 3/4, 7/8). */
private val SUB_DIVISOR_CODE = intArrayOf(0, 3, 2, 4, 1, 5, 6, 7)

/** UARTs tolerate about 3 % clock difference between the two ends; beyond that bytes garble. */
internal const val MAX_BAUD_ERROR = 0.03

internal fun ftdiBaudDivisor(baudRate: Int): FtdiBaudDivisor {
    if (baudRate > 3_500_000) throw UnsupportedSettingException("FTDI chips run at most 3000000 baud, not $baudRate")
    val (whole, eighths, actual) = when {
        baudRate >= 2_500_000 -> Triple(0, 0, 3_000_000)
        baudRate >= 1_750_000 -> Triple(1, 0, 2_000_000)
        else -> {
            val total = ((BASE_CLOCK_EIGHTHS * 2 / baudRate + 1) / 2).toInt() // rounded to the nearest eighth
            // Between 1 and 2 only the special value 1 exists, so fall back to a whole divisor of 2.
            val divisor = if (total < 16) 16 else total
            if (divisor shr 3 > 0x3FFF) throw UnsupportedSettingException("FTDI chips run at least 183 baud, not $baudRate")
            Triple(divisor shr 3, divisor and 7, ((BASE_CLOCK_EIGHTHS * 2 / divisor + 1) / 2).toInt())
        }
    }
    val error = abs(actual.toDouble() / baudRate - 1)
    if (error > MAX_BAUD_ERROR) {
        throw UnsupportedSettingException("FTDI chips cannot do $baudRate baud: the nearest is $actual")
    }
    val code = SUB_DIVISOR_CODE[eighths]
    return FtdiBaudDivisor(value = whole or ((code and 3) shl 14), indexBit = code shr 2, actualBaudRate = actual)
}
