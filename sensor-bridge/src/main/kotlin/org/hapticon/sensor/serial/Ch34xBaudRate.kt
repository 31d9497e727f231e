package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import kotlin.math.abs

/** The CH34x's UART clock. */
private const val CLOCK_HZ = 48_000_000L

/**
 * The CH34x prescaler/divisor register pair 0x12/0x13 for [baudRate], without bit 7 (which the
 * port adds on chips that need it). The chip divides 48 MHz by a prescaler `2^(12 - 3 ps - fact)`
 * (ps 0..3, fact 0..1) and by an 8-bit divisor stored as `0x100 - div`. The search follows the
 * Linux ch341 driver: the highest prescaler that keeps div below 512, round div to the nearest
 * rate, and prefer fact = 0 when div is even (the receiver tolerates more error then).
 *
 * @return `(0x100 - div) << 8 | fact << 2 | ps`.
 * @throws UnsupportedSettingException outside 46..3000000 baud or more than 3 % off.
 */
internal fun ch34xBaudDivisor(baudRate: Int): Int {
    if (baudRate !in 46..3_000_000) throw UnsupportedSettingException("CH34x chips run at 46 to 3000000 baud, not $baudRate")
    val ps = (3 downTo 0).firstOrNull { baudRate > CLOCK_HZ / (prescaler(it, 1) * 512) }
        ?: throw UnsupportedSettingException("CH34x chips cannot do $baudRate baud")
    var fact = 1
    var clockDivider = prescaler(ps, fact)
    var div = CLOCK_HZ / (clockDivider * baudRate)
    if (div < 9 || div > 255) {
        div /= 2
        clockDivider *= 2
        fact = 0
    }
    if (div < 2) throw UnsupportedSettingException("CH34x chips cannot do $baudRate baud")
    // Take div + 1 if its rate is nearer; scaled by 16 so low rates round correctly.
    val above = 16 * CLOCK_HZ / (clockDivider * div) - 16L * baudRate
    val below = 16L * baudRate - 16 * CLOCK_HZ / (clockDivider * (div + 1))
    if (above >= below) div++
    if (fact == 1 && div % 2 == 0L) {
        div /= 2
        clockDivider *= 2
        fact = 0
    }
    val actual = CLOCK_HZ / (clockDivider * div)
    if (abs(actual.toDouble() / baudRate - 1) > MAX_BAUD_ERROR) {
        throw UnsupportedSettingException("CH34x chips cannot do $baudRate baud: the nearest is $actual")
    }
    return ((0x100 - div.toInt()) shl 8) or (fact shl 2) or ps
}

private fun prescaler(ps: Int, fact: Int): Long = 1L shl (12 - 3 * ps - fact)
