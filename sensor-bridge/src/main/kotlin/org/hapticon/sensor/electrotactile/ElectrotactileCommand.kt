package org.hapticon.sensor.electrotactile

import org.hapticon.sensor.safety.SafetyLimits

/**
 * A person's calibrated electrotactile maximum, [maxMilliamps], at most the hard cap
 * [SafetyLimits.ELECTROTACTILE_MAX_MILLIAMPS] (2.7 mA).
 * @throws org.hapticon.sensor.safety.SafetyLimitException from the constructor when it is not in (0, 2.7] mA.
 */
public data class ElectrotactileUserLimit(val maxMilliamps: Double) {
    init {
        SafetyLimits.requireElectrotactileUserMaximum(maxMilliamps)
    }
}

/** Which way the stimulating current flows at the active electrodes. */
public enum class PulsePolarity {
    /** The active electrodes are the anode (positive). */
    ANODIC,

    /** The active electrodes are the cathode (negative). */
    CATHODIC,
}

/**
 * The timing of one electrotactile burst: [pulseCount] rectangular monophasic pulses of [pulseWidthMicros] µs
 * at [frequencyHz] (pulse onsets 1/f apart) with [polarity]. [GRAIN] is the compliance-grain burst: 2 anodic
 * pulses of 200 µs at 125 Hz (Shaping Compliance, 003_8ca1dc8f53472543.txt:99).
 *
 * The bounds checked here (1–1000 Hz, 1–1000 µs, 1–100 pulses, pulse shorter than the period) are sanity
 * checks, not study values.
 */
public data class PulseTrain(
    val frequencyHz: Double = GRAIN_FREQUENCY_HZ,
    val pulseCount: Int = GRAIN_PULSE_COUNT,
    val pulseWidthMicros: Double = GRAIN_PULSE_WIDTH_MICROS,
    val polarity: PulsePolarity = PulsePolarity.ANODIC,
) {
    init {
        require(frequencyHz >= 1.0 && frequencyHz <= 1000.0) { "frequencyHz must be in [1, 1000], was $frequencyHz" }
        require(pulseCount in 1..100) { "pulseCount must be in 1..100, was $pulseCount" }
        require(pulseWidthMicros >= 1.0 && pulseWidthMicros <= 1000.0) { "pulseWidthMicros must be in [1, 1000], was $pulseWidthMicros" }
        require(pulseWidthMicros < 1e6 / frequencyHz) { "a $pulseWidthMicros µs pulse does not fit in a ${1e6 / frequencyHz} µs period" }
    }

    /** Time from the first pulse's onset to the last pulse's end: (count − 1)/f + width, in seconds. */
    public val durationSeconds: Double get() = (pulseCount - 1) / frequencyHz + pulseWidthMicros * 1e-6

    public companion object {
        /** The grain burst's pulse rate. */
        public const val GRAIN_FREQUENCY_HZ: Double = 125.0

        /** Pulses per grain. */
        public const val GRAIN_PULSE_COUNT: Int = 2

        /** The grain burst's pulse width. */
        public const val GRAIN_PULSE_WIDTH_MICROS: Double = 200.0

        /** The compliance-grain burst: 2 anodic 200 µs pulses at 125 Hz (8.2 ms). */
        public val GRAIN: PulseTrain = PulseTrain()
    }
}

/**
 * One burst on the 3×3 electrode array: [pulses] through the electrodes of [pattern] at [currentMilliamps].
 *
 * The current is checked here, in the only constructor, against both the hard cap (2.7 mA) and [userLimit]:
 * no code path can hold an over-limit command. (A data class `copy` runs the same check.)
 * @throws org.hapticon.sensor.safety.SafetyLimitException from the constructor when [currentMilliamps] is not
 *   in (0, [ElectrotactileUserLimit.maxMilliamps]] or not finite.
 */
public data class ElectrotactileCommand(
    val pattern: ElectrodePattern,
    val currentMilliamps: Double,
    val userLimit: ElectrotactileUserLimit,
    val pulses: PulseTrain = PulseTrain.GRAIN,
) {
    init {
        SafetyLimits.requireElectrotactileCurrent(currentMilliamps, userLimit.maxMilliamps)
    }

    /** Charge per pulse and electrode in microcoulombs: current × width (0.54 µC at 2.7 mA and 200 µs). */
    public val chargePerPulseMicrocoulombs: Double get() = currentMilliamps * pulses.pulseWidthMicros * 1e-3
}
