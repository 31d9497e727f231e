package org.hapticon.sensor.grains

/**
 * Force from an Interlink 402 FSR read through a voltage divider, approximately.
 *
 * Circuit (Interlink's integration guide): the FSR runs from the supply [supplyVolts] to the output node, the
 * measuring resistor [measuringKiloohms] from the output node to ground, so Vout = Vin·RM/(RM + R_FSR) rises
 * with force. The FSR's conductance is G = 1/R_FSR = Vout/(RM·(Vin − Vout)), and over the sensor's useful
 * range G is roughly proportional to force: F ≈ G/[microsiemensPerNewton]. The default 80 µS/N is the
 * common rule of thumb for the 402 with a 10 kΩ resistor (about 0–12 N, G ≤ 1000 µS); real sensors vary by
 * tens of percent between parts and saturate above that, so calibrate with weights for quantitative work.
 *
 * Vout ≤ 0 V means no touch (R_FSR = ∞, G = 0) and gives 0 N; Vout ≥ Vin (FSR shorted) and NaN are faults.
 */
public data class FsrForceConverter(
    val measuringKiloohms: Double = DEFAULT_MEASURING_KILOOHMS,
    val supplyVolts: Double = DEFAULT_SUPPLY_VOLTS,
    val microsiemensPerNewton: Double = DEFAULT_MICROSIEMENS_PER_NEWTON,
) {
    init {
        require(measuringKiloohms > 0.0 && measuringKiloohms <= 1.0e6) { "measuringKiloohms must be in (0, 1e6] kΩ, was $measuringKiloohms" }
        require(supplyVolts > 0.0 && supplyVolts <= 50.0) { "supplyVolts must be in (0, 50] V, was $supplyVolts" }
        require(microsiemensPerNewton > 0.0 && microsiemensPerNewton.isFinite()) { "microsiemensPerNewton must be finite and > 0, was $microsiemensPerNewton" }
    }

    /** The force for a divider output of [volts], or the fault that prevents one. */
    public fun forceOf(volts: Double): FsrReading {
        if (volts.isNaN()) return FsrReading.Fault(FsrFault.NOT_A_NUMBER, volts)
        if (volts >= supplyVolts) return FsrReading.Fault(FsrFault.SHORTED, volts)
        if (volts <= 0.0) return FsrReading.Force(0.0, 0.0)
        // kΩ → µS: 1/(R kΩ) = 1000/R µS.
        val microsiemens = 1000.0 * volts / (measuringKiloohms * (supplyVolts - volts))
        if (!microsiemens.isFinite()) return FsrReading.Fault(FsrFault.SHORTED, volts)
        return FsrReading.Force(microsiemens / microsiemensPerNewton, microsiemens)
    }

    /**
     * The force in N for [volts] as [forceOf] gives it, or NaN for a fault: the allocation-free form for
     * per-sample paths ([forceOf] says why there is no value).
     */
    public fun newtonsOrNaN(volts: Double): Double {
        if (volts.isNaN() || volts >= supplyVolts) return Double.NaN
        if (volts <= 0.0) return 0.0
        val microsiemens = 1000.0 * volts / (measuringKiloohms * (supplyVolts - volts))
        return if (microsiemens.isFinite()) microsiemens / microsiemensPerNewton else Double.NaN
    }

    public companion object {
        /** Interlink's suggested measuring resistor. */
        public const val DEFAULT_MEASURING_KILOOHMS: Double = 10.0

        /** Default supply. */
        public const val DEFAULT_SUPPLY_VOLTS: Double = 5.0

        /** Default conductance per newton (rule of thumb for the Interlink 402). */
        public const val DEFAULT_MICROSIEMENS_PER_NEWTON: Double = 80.0
    }
}

/** What an FSR reading says: a force, or why there is none. */
public sealed interface FsrReading {
    /** [newtons] ≥ 0 (approximate) from a conductance of [microsiemens]. */
    public data class Force(val newtons: Double, val microsiemens: Double) : FsrReading

    /** A fault: [fault] says which, [volts] is the offending output. */
    public data class Fault(val fault: FsrFault, val volts: Double) : FsrReading
}

/** Why an FSR reading could not be turned into a force. */
public enum class FsrFault {
    /** The output is NaN. */
    NOT_A_NUMBER,

    /** The output is at or above the supply: the FSR or its wiring is shorted. */
    SHORTED,
}
