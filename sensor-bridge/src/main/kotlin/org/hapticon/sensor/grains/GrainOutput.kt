package org.hapticon.sensor.grains

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.electrotactile.ElectrodePattern
import org.hapticon.sensor.electrotactile.ElectrotactileCommand
import org.hapticon.sensor.electrotactile.ElectrotactileUserLimit
import org.hapticon.sensor.electrotactile.PulseTrain
import org.hapticon.sensor.safety.SafetyLimits

/**
 * A grain as a short burst on the phone's LRA: [amplitude] (1..255) for [durationSeconds] (at least 1 ms,
 * at most the vibration cap), rectangular.
 * @throws org.hapticon.sensor.safety.SafetyLimitException from the constructor when either is out of range.
 */
public data class LraGrain(val durationSeconds: Double = GrainSettings.DEFAULT_GRAIN_SECONDS, val amplitude: Int = SafetyLimits.VIBRATION_AMPLITUDE_MAX) {
    init {
        SafetyLimits.requireVibrationSeconds(durationSeconds)
        SafetyLimits.requireVibrationAmplitude(amplitude)
        require(amplitude >= 1) { "a grain needs an amplitude >= 1, was $amplitude" }
        require(durationSeconds >= MIN_SECONDS) { "a grain must last at least 1 ms (Android's timing unit), was $durationSeconds s" }
    }

    /**
     * The burst for `VibrationEffect.createWaveform`: one entry of round(duration) ms at [amplitude]
     * (via [VibrationWaveform.amplitudeSteps] with a constant envelope).
     */
    public fun waveform(): VibrationWaveform =
        VibrationWaveform.amplitudeSteps({ amplitude.toDouble() / SafetyLimits.VIBRATION_AMPLITUDE_MAX }, durationSeconds)

    /**
     * The burst as a haptic icon: a [LRA_NOTE] carrier (174.6 Hz, near a typical phone LRA's resonance) held
     * at amplitude/255 for the whole duration with no attack or release, played once.
     */
    public fun icon(): HapticIcon =
        HapticIcon("grain", 0.0, durationSeconds, amplitude.toDouble() / SafetyLimits.VIBRATION_AMPLITUDE_MAX, 0.0, LRA_NOTE)

    public companion object {
        /** MIDI note 53, 174.6 Hz. */
        public const val LRA_NOTE: Double = 53.0

        /** Shortest grain: 1 ms. */
        public const val MIN_SECONDS: Double = 0.001
    }
}

/**
 * How each grain is rendered: once on the phone's LRA, or as an electrotactile burst. Build it once; the
 * command it holds was checked against the safety limits when it was built.
 */
public sealed interface GrainOutput {
    /** Grains as LRA bursts. */
    public data class Lra(val grain: LraGrain) : GrainOutput

    /** Grains as [command] on the electrode array (one command per grain). */
    public data class Electrotactile(val command: ElectrotactileCommand) : GrainOutput

    public companion object {
        /**
         * The electrotactile grain: [mask] driven with [PulseTrain.GRAIN] (2 anodic 200 µs pulses at 125 Hz) at
         * [currentMilliamps].
         * @throws org.hapticon.sensor.safety.SafetyLimitException when the current exceeds [userLimit] or 2.7 mA.
         */
        public fun electrotactile(mask: ElectrodeMask, currentMilliamps: Double, userLimit: ElectrotactileUserLimit): Electrotactile =
            electrotactile(mask.pattern, currentMilliamps, userLimit)

        /**
         * The electrotactile grain on any [pattern] of at least [ElectrodePattern.MIN_COMPLIANCE_ELECTRODES]
         * electrodes (Shaping Compliance: fewer felt too weak, 003_8ca1dc8f53472543.txt:107).
         * @throws IllegalArgumentException when [pattern] has fewer than 4 electrodes.
         * @throws org.hapticon.sensor.safety.SafetyLimitException when the current exceeds [userLimit] or 2.7 mA.
         */
        public fun electrotactile(pattern: ElectrodePattern, currentMilliamps: Double, userLimit: ElectrotactileUserLimit): Electrotactile {
            require(pattern.isStrongEnoughForCompliance) {
                "a compliance grain needs at least ${ElectrodePattern.MIN_COMPLIANCE_ELECTRODES} electrodes (fewer felt too weak), $pattern has ${pattern.activeCount}"
            }
            return Electrotactile(ElectrotactileCommand(pattern, currentMilliamps, userLimit, PulseTrain.GRAIN))
        }
    }
}
