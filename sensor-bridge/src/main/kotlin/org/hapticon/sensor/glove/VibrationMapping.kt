package org.hapticon.sensor.glove

import org.hapticon.sensor.safety.SafetyLimits
import kotlin.math.floor

/**
 * Interaction pressure as a vibration amplitude for a phone without a glove: during a handshake,
 * amplitude = round(floor + (255 − floor)·n) with n = (P − Pmin)/(Pmax − Pmin) clamped to [0, 1] (halves
 * up); outside a handshake 0.
 *
 * The floor (default 40, about 16 % of full scale) makes the lightest contact, P = Pmin, still felt: phone
 * LRAs barely move below roughly 10–20 % drive, so a plain linear map would leave the start of every
 * handshake silent. The mapping is linear above the floor because the pressure scale is itself a sensor
 * voltage, not a perceptual scale.
 */
public data class VibrationMapping(val floorAmplitude: Int = DEFAULT_FLOOR_AMPLITUDE) {
    init {
        require(floorAmplitude in 1..SafetyLimits.VIBRATION_AMPLITUDE_MAX) {
            "floorAmplitude must be in 1..${SafetyLimits.VIBRATION_AMPLITUDE_MAX}, was $floorAmplitude"
        }
    }

    /**
     * The amplitude 0..255 for [pressureVolts] in [region], or 0 when [active] is false. Allocation-free.
     * @throws IllegalArgumentException when [pressureVolts] is NaN.
     */
    public fun amplitudeFor(region: HandRegion, pressureVolts: Double, active: Boolean): Int {
        require(!pressureVolts.isNaN()) { "pressure must not be NaN" }
        if (!active) return SafetyLimits.VIBRATION_AMPLITUDE_MIN
        val n = ((pressureVolts - region.minPressureVolts) / region.pressureRangeVolts).coerceIn(0.0, 1.0)
        val amplitude = floor(floorAmplitude + (SafetyLimits.VIBRATION_AMPLITUDE_MAX - floorAmplitude) * n + 0.5).toInt()
        return amplitude.coerceIn(floorAmplitude, SafetyLimits.VIBRATION_AMPLITUDE_MAX)
    }

    public companion object {
        /** Default amplitude at P = Pmin during a handshake. */
        public const val DEFAULT_FLOOR_AMPLITUDE: Int = 40
    }
}
