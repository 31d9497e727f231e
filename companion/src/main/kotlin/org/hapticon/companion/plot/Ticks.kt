package org.hapticon.companion.plot

import java.util.Locale
import kotlin.math.ceil
import kotlin.math.floor
import kotlin.math.log10
import kotlin.math.max
import kotlin.math.pow

/** Evenly spaced axis ticks at "nice" steps (1, 2 or 5 × 10^k), with labels that show just enough decimals. */
class Ticks private constructor(
    /** Tick values in increasing order. */
    val values: List<Double>,
    private val decimals: Int,
) {
    /** [value] formatted with this tick set's number of decimals, e.g. `0.25`. */
    fun label(value: Double): String = String.format(Locale.ROOT, "%.${decimals}f", value)

    companion object {
        /** Ticks covering [from, to] with a nice step chosen to give at most [maxTicks] ticks. */
        fun between(from: Double, to: Double, maxTicks: Int = 10): Ticks {
            require(to > from && maxTicks >= 2) { "need a non-empty range and at least 2 ticks" }
            val step = niceStep((to - from) / (maxTicks - 1))
            val first = ceil(from / step - 1e-9).toLong()
            val last = floor(to / step + 1e-9).toLong()
            val values = (first..last).map { it * step }
            val decimals = max(0, -floor(log10(step) + 1e-9).toInt())
            return Ticks(values, decimals)
        }

        /** The smallest 1, 2 or 5 × 10^k that is at least [rawStep]. */
        private fun niceStep(rawStep: Double): Double {
            val magnitude = 10.0.pow(floor(log10(rawStep)))
            for (multiple in listOf(1.0, 2.0, 5.0, 10.0)) {
                if (multiple * magnitude >= rawStep * (1 - 1e-9)) return multiple * magnitude
            }
            return 10.0 * magnitude
        }
    }
}
