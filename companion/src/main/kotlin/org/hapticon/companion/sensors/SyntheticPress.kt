package org.hapticon.companion.sensors

import org.hapticon.sensor.grains.FsrForceConverter
import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.roundToInt

/**
 * A finger pressing an Interlink 402 FSR, made up for the demo and the bench (no recording ships with the
 * tool): the force over time, and the 12-bit ADC counts a board reading the FSR's divider would send.
 *
 * Each [PERIOD_SECONDS] cycle rests for 0.2 s, presses to [PEAK_NEWTONS] along a raised cosine over 0.8 s,
 * holds for 0.4 s and releases over 0.6 s, so the force sweeps every grain bin up and down once.
 */
object SyntheticPress {
    /** Samples per second, a typical FSR board rate. */
    const val SAMPLE_RATE_HZ: Int = 1000

    /** ADC resolution (ESP32, or an Arduino's 10 bits scaled). */
    const val ADC_BITS: Int = 12

    /** Length of one press-and-release cycle. */
    const val PERIOD_SECONDS: Double = 2.0

    /** Strongest force of a press: the default grain range's top. */
    const val PEAK_NEWTONS: Double = 10.0

    private const val REST = 0.2
    private const val PRESS = 0.8
    private const val HOLD = 0.4
    private const val RELEASE = 0.6
    private val FULL_SCALE = (1 shl ADC_BITS) - 1

    /** The force in newtons at [seconds]. */
    fun newtons(seconds: Double): Double {
        val t = seconds % PERIOD_SECONDS
        return when {
            t < REST -> 0.0
            t < REST + PRESS -> PEAK_NEWTONS * rise((t - REST) / PRESS)
            t < REST + PRESS + HOLD -> PEAK_NEWTONS
            t < REST + PRESS + HOLD + RELEASE -> PEAK_NEWTONS * (1 - rise((t - REST - PRESS - HOLD) / RELEASE))
            else -> 0.0
        }
    }

    /**
     * The divider output in volts for [newtons] under [converter]'s circuit: the inverse of
     * [FsrForceConverter.forceOf]. G = F·k µS, R_FSR = 1000/G kΩ, Vout = Vin·RM/(RM + R_FSR).
     */
    fun volts(newtons: Double, converter: FsrForceConverter = FsrForceConverter()): Double {
        if (newtons <= 0.0) return 0.0
        val fsrKiloohms = 1000.0 / (newtons * converter.microsiemensPerNewton)
        return converter.supplyVolts * converter.measuringKiloohms / (converter.measuringKiloohms + fsrKiloohms)
    }

    /** The ADC counts (0..4095) of [volts] measured against [supplyVolts]. */
    fun counts(volts: Double, supplyVolts: Double = FsrForceConverter.DEFAULT_SUPPLY_VOLTS): Int =
        (volts / supplyVolts * FULL_SCALE).roundToInt().coerceIn(0, FULL_SCALE)

    /** The volts that [counts] stand for: the inverse of [counts], to one ADC step. */
    fun voltsOfCounts(counts: Int, supplyVolts: Double = FsrForceConverter.DEFAULT_SUPPLY_VOLTS): Double = counts * supplyVolts / FULL_SCALE

    /** The counts the board sends for sample [index]. */
    fun countsAt(index: Int): Int = counts(volts(newtons(index.toDouble() / SAMPLE_RATE_HZ)))

    private fun rise(x: Double): Double = (1 - cos(PI * x)) / 2
}
