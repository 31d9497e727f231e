package org.hapticon.companion.plot

import org.hapticon.core.HapticIcon
import java.math.BigDecimal
import java.util.Locale

/** How plots write icon parameters: shortest exact decimals, seconds marked. */
object IconText {
    /** All parameters on one line, e.g. `attack 0.005 s · sustain 0.01 s · level 0.5 · … · period 0.27 s × 3`. */
    fun parameters(icon: HapticIcon): String {
        val repetition = if (icon.count > 1) " · period ${number(icon.period)} s × ${icon.count}" else " · once"
        return "attack ${number(icon.attack)} s · sustain ${number(icon.sustain)} s · level ${number(icon.level)}" +
            " · release ${number(icon.release)} s · note ${number(icon.note)} (${hertz(icon.frequency)})" +
            repetition + " · ${number(icon.duration)} s in all"
    }

    /** [value] in its shortest exact decimal form without exponent: 1.0 → `1`, 0.005 → `0.005`. */
    fun number(value: Double): String = BigDecimal(value.toString()).stripTrailingZeros().toPlainString()

    /** A frequency such as `220.0 Hz`. */
    fun hertz(frequency: Double): String = String.format(Locale.ROOT, "%.1f Hz", frequency)
}
