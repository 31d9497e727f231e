package org.hapticon.sensor.glove

/**
 * One flex sensor from ADC counts to a bend angle: counts → Vout ([adc]) → R ([divider]) → θ ([calibration]).
 * Faults at any step come back as [AngleReading.Fault], so no NaN or ∞ angle is ever produced.
 */
public data class FlexSensorChannel(
    val calibration: FlexCalibration,
    val divider: FlexDivider = FlexDivider(),
    val adc: AdcScale = AdcScale.TEN_BIT,
) {
    /** The angle for an ADC reading of [counts], or the fault that prevents one. */
    public fun angleOfCounts(counts: Int): AngleReading {
        if (!adc.isValid(counts)) return AngleReading.Fault(SensorFault.COUNT_OUT_OF_RANGE)
        return angleOfVolts(adc.voltsOf(counts))
    }

    /** The angle for a divider output of [volts], or the fault that prevents one. */
    public fun angleOfVolts(volts: Double): AngleReading = when (val reading = divider.resistanceOf(volts)) {
        is DividerReading.Fault -> AngleReading.Fault(reading.fault)
        is DividerReading.Resistance -> AngleReading.Angle(calibration.angleOf(reading.kiloohms))
    }
}

/** A bend angle, or why there is none. */
public sealed interface AngleReading {
    /** A finite bend angle in degrees (may be negative or beyond 90°; the pressure model clamps). */
    public data class Angle(val degrees: Double) : AngleReading

    /** The sensor is faulty; the app should treat the finger as open (0°), which releases actuators. */
    public data class Fault(val fault: SensorFault) : AngleReading
}
