package org.hapticon.sensor.glove

/**
 * A flex sensor read through a voltage divider: the fixed resistor [fixedKiloohms] runs from the supply
 * [supplyVolts] to the output node and the flex sensor from the output node to ground, so
 * Vout = Vin·R/(R + Rfix) and the sensor's resistance is R = Vout/(Vin − Vout)·Rfix, the tele-handshake paper's
 * Eq. 4 (002_12aacdd60a14fec1.txt:63; its circuit is only its Figure 4, :231, so the topology is the one Eq. 4
 * implies: R rises with Vout).
 *
 * Resistances are in kΩ throughout the glove model, the unit of the study's calibration constant β.
 * A reading at or below 0 V (sensor shorted to ground, R = 0), at or above the supply (sensor open or
 * unplugged, R = ∞) or NaN is reported as a [DividerReading.Fault]; the result is never 0, ∞ or NaN.
 */
public data class FlexDivider(
    val fixedKiloohms: Double = DEFAULT_FIXED_KILOOHMS,
    val supplyVolts: Double = DEFAULT_SUPPLY_VOLTS,
) {
    init {
        require(fixedKiloohms > 0.0 && fixedKiloohms <= MAX_FIXED_KILOOHMS) {
            "fixedKiloohms must be in (0, $MAX_FIXED_KILOOHMS] kΩ, was $fixedKiloohms"
        }
        require(supplyVolts > 0.0 && supplyVolts <= MAX_SUPPLY_VOLTS) {
            "supplyVolts must be in (0, $MAX_SUPPLY_VOLTS] V, was $supplyVolts"
        }
    }

    /**
     * The sensor's resistance for an output of [volts]: R = Vout/(Vin − Vout)·Rfix in kΩ, or a fault when
     * [volts] is NaN, ≤ 0 or ≥ [supplyVolts].
     */
    public fun resistanceOf(volts: Double): DividerReading {
        val fault = faultOf(volts)
        if (fault != null) return DividerReading.Fault(fault, volts)
        val kiloohms = resistanceOrNaN(volts)
        // A subnormal Vout underflows R to 0 (ln R = −∞ downstream): that is a short in all but name;
        // Vout one ulp below Vin still gives a finite R with the bounded Rfix, so ∞ is defensive only.
        if (kiloohms.isNaN()) return DividerReading.Fault(if (volts < supplyVolts / 2) SensorFault.SHORT_CIRCUIT else SensorFault.OPEN_CIRCUIT, volts)
        return DividerReading.Resistance(kiloohms)
    }

    /**
     * The resistance for [volts] in kΩ as [resistanceOf] gives it, or NaN for any fault: the allocation-free
     * form for per-sample paths, which only need to know that there is no value ([resistanceOf] says why).
     */
    public fun resistanceOrNaN(volts: Double): Double {
        if (faultOf(volts) != null) return Double.NaN
        val kiloohms = volts / (supplyVolts - volts) * fixedKiloohms
        return if (kiloohms > 0.0 && kiloohms.isFinite()) kiloohms else Double.NaN
    }

    /** The output voltage the divider gives for a sensor of [kiloohms] (> 0, finite): Vin·R/(R + Rfix). */
    public fun voltsFor(kiloohms: Double): Double {
        require(kiloohms > 0.0 && kiloohms.isFinite()) { "kiloohms must be finite and > 0, was $kiloohms" }
        return supplyVolts * kiloohms / (kiloohms + fixedKiloohms)
    }

    /**
     * How far the output moves while a finger following [calibration] bends from [fromDegrees] to [toDegrees]:
     * Vout(to) − Vout(from), in volts. With the paper's printed 22 Ω and a 16 kΩ sensor this is about 5 mV over
     * 0–90°, one count of a 10-bit ADC; with [DEFAULT_FIXED_KILOOHMS], 1.7 V.
     */
    public fun swingVolts(calibration: FlexCalibration, fromDegrees: Double = 0.0, toDegrees: Double = 90.0): Double =
        voltsFor(calibration.resistanceAt(toDegrees)) - voltsFor(calibration.resistanceAt(fromDegrees))

    private fun faultOf(volts: Double): SensorFault? = when {
        volts.isNaN() -> SensorFault.NOT_A_NUMBER
        volts <= 0.0 -> SensorFault.SHORT_CIRCUIT
        volts >= supplyVolts -> SensorFault.OPEN_CIRCUIT
        else -> null
    }

    public companion object {
        /** The tele-handshake paper's supply: "Input voltage V in is 5 V" (002_12aacdd60a14fec1.txt:62). */
        public const val DEFAULT_SUPPLY_VOLTS: Double = 5.0

        /**
         * The fixed resistor as the tele-handshake paper prints it, "the fixed resistance R fix is 22 Ω"
         * (002_12aacdd60a14fec1.txt:62), in kΩ. Not usable with its own sensor: Table 1's β ≈ 16 kΩ at 0° and
         * ≈ 68 kΩ at 90° (:259-262) put Vout within 7 mV of the 5 V supply over the whole bend, a swing of
         * about 5 mV (one count of a 10-bit ADC, 90° per count). By Eq. 4 (:63) R comes out in Rfix's unit, and
         * β ≈ 16 is a flex sensor's resistance only in kΩ, so "22 Ω" reads as a slip for 22 kΩ
         * ([PAPER_READ_AS_KILOOHMS]); `hapticon replicate handshake` prints the swing of each.
         */
        public const val PAPER_PRINTED_FIXED_KILOOHMS: Double = 0.022

        /** 22 kΩ: the paper's printed "22 Ω" (002_12aacdd60a14fec1.txt:62) read in the kΩ of its β (:259-262). */
        public const val PAPER_READ_AS_KILOOHMS: Double = 22.0

        /**
         * Ours, 33 kΩ: the E6 value nearest [widestSwingKiloohms] of the paper's mean thumb at 0° and 90°,
         * √(16.17 kΩ · 68.2 kΩ) = 33.2 kΩ (Table 1, 002_12aacdd60a14fec1.txt:259-260), which maximises the output
         * swing over that bend: 1.73 V, 4 % more than [PAPER_READ_AS_KILOOHMS]'s 1.66 V.
         */
        public const val DEFAULT_FIXED_KILOOHMS: Double = 33.0

        /**
         * The fixed resistor that gives the widest swing between sensor resistances [lowKiloohms] and
         * [highKiloohms]: √(low·high), where d/dRfix of Vin·(high/(high + Rfix) − low/(low + Rfix)) is zero.
         */
        public fun widestSwingKiloohms(lowKiloohms: Double, highKiloohms: Double): Double {
            require(lowKiloohms > 0.0 && highKiloohms > 0.0 && lowKiloohms.isFinite() && highKiloohms.isFinite()) {
                "resistances must be finite and > 0, were $lowKiloohms and $highKiloohms"
            }
            return kotlin.math.sqrt(lowKiloohms * highKiloohms)
        }

        /** Largest fixed resistor accepted (1 GΩ); bounds R so that it stays finite. */
        public const val MAX_FIXED_KILOOHMS: Double = 1.0e6

        /** Largest supply accepted. */
        public const val MAX_SUPPLY_VOLTS: Double = 50.0
    }
}

/** What a voltage-divider reading says: a resistance, or why there is none. */
public sealed interface DividerReading {
    /** A valid reading: the sensor's resistance in kΩ, finite and > 0. */
    public data class Resistance(val kiloohms: Double) : DividerReading

    /** A sensor fault: [fault] says which, [volts] is the offending output (for logs). */
    public data class Fault(val fault: SensorFault, val volts: Double) : DividerReading
}

/** Why a sensor reading could not be turned into a value. */
public enum class SensorFault {
    /** The output is NaN (a decoding or arithmetic error upstream). */
    NOT_A_NUMBER,

    /** The output is at or below 0 V: the sensor or its wire is shorted to ground. */
    SHORT_CIRCUIT,

    /** The output is at or above the supply: the sensor is open or unplugged. */
    OPEN_CIRCUIT,

    /** An ADC count outside 0..full scale: the sample was corrupted in transfer. */
    COUNT_OUT_OF_RANGE,
}

/**
 * An ADC of [bits] resolution referenced to [referenceVolts]: counts 0..2^bits − 1 map linearly onto
 * 0..Vref, Vout = counts/(2^bits − 1)·Vref. Full scale maps to exactly Vref, so a saturated input (an open
 * flex sensor) reads as the supply and is reported as a fault rather than as a huge resistance.
 */
public data class AdcScale(val bits: Int, val referenceVolts: Double = FlexDivider.DEFAULT_SUPPLY_VOLTS) {
    init {
        require(bits in MIN_BITS..MAX_BITS) { "bits must be in $MIN_BITS..$MAX_BITS, was $bits" }
        require(referenceVolts > 0.0 && referenceVolts <= FlexDivider.MAX_SUPPLY_VOLTS) {
            "referenceVolts must be in (0, ${FlexDivider.MAX_SUPPLY_VOLTS}] V, was $referenceVolts"
        }
    }

    /** The largest count, 2^bits − 1 (1023 for 10 bits, 4095 for 12 bits). */
    public val fullScale: Int get() = (1 shl bits) - 1

    /** Whether [counts] is a count this ADC can produce, 0..[fullScale]. */
    public fun isValid(counts: Int): Boolean = counts in 0..fullScale

    /**
     * Vout in volts for [counts]: counts/[fullScale]·[referenceVolts].
     * @throws IllegalArgumentException when [counts] is outside 0..[fullScale].
     */
    public fun voltsOf(counts: Int): Double {
        require(isValid(counts)) { "counts must be in 0..$fullScale, was $counts" }
        return counts.toDouble() / fullScale * referenceVolts
    }

    public companion object {
        /** Fewest bits accepted. */
        public const val MIN_BITS: Int = 8

        /** Most bits accepted. */
        public const val MAX_BITS: Int = 16

        /** A 10-bit ADC at 5 V (Arduino Uno/Nano). */
        public val TEN_BIT: AdcScale = AdcScale(10)

        /** A 12-bit ADC at 5 V. */
        public val TWELVE_BIT: AdcScale = AdcScale(12)
    }
}
