package org.hapticon.sensor.grains

import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.CalibrationStimulus
import org.hapticon.sensor.electrotactile.ElectrotactileCalibration
import org.hapticon.sensor.protocol.framed.FramedEncoder

/**
 * One calibration stimulus for the reference firmware (firmware/hapticon_ref/grains.h `Stimulus`), sent with the
 * framed protocol's STIMULATE command ([stimulate]): the grain's pulses (200 µs, anodic) every 8 ms (125 Hz) for
 * [durationMillis] on [electrode] alone at amplitude [step]. Shaping Compliance (003_8ca1dc8f53472543.txt:152) calibrates each electrode alone
 * with a 200 ms stimulus rising from 0.8 mA, so this is the one command that drives fewer than 4 electrodes: the
 * 4-electrode minimum is the compliance grains' (too weak in the pilot), not a calibration's. The 2.7 mA cap holds.
 * Checked here as the firmware checks it, so a refused stimulus never reaches the wire.
 * @throws IllegalArgumentException for an electrode outside 0..8 or a duration outside 1..[MAX_DURATION_MILLIS];
 *   [org.hapticon.sensor.safety.SafetyLimitException] for a step outside 0..200 (above 2.7 mA).
 */
public data class FirmwareStimulus(
    val electrode: Int,
    val step: Int,
    val durationMillis: Int = ElectrotactileCalibration.STIMULUS_MILLIS,
) {
    init {
        require(electrode in 0 until ElectrotactileCalibration.ELECTRODES) { "electrode must be in 0..8, was $electrode" }
        AmplitudeSteps.requireStep(step)
        require(durationMillis in 1..MAX_DURATION_MILLIS) { "a stimulus lasts 1..$MAX_DURATION_MILLIS ms, was $durationMillis" }
    }

    /** Pulses the board gives: one per started 8 ms period (25 for 200 ms). */
    public val pulseCount: Int get() = (durationMillis * 1000 + PULSE_PERIOD_MICROS - 1) / PULSE_PERIOD_MICROS

    /** The 4-byte STIMULATE payload: electrode, step, duration u16 little-endian (ms), in grains.h's order. */
    public fun payload(): ByteArray = byteArrayOf(
        electrode.toByte(),
        step.toByte(),
        durationMillis.toByte(),
        (durationMillis ushr 8).toByte(),
    )

    public companion object {
        /** Bytes of the payload. */
        public const val PAYLOAD_LENGTH: Int = 4

        /** The longest stimulus the firmware takes (the paper's are 200 ms): a stuck host cannot hold a current on. */
        public const val MAX_DURATION_MILLIS: Int = 1000

        private const val PULSE_PERIOD_MICROS = 8000

        /**
         * The firmware stimulus for a per-electrode step of [ElectrotactileCalibration] ([ElectrotactileCalibration.stimulus]).
         * @throws IllegalArgumentException for the whole-array check (grains on every electrode: [FirmwareGrainParams]).
         */
        public fun of(stimulus: CalibrationStimulus): FirmwareStimulus {
            require(stimulus.grains == 0 && stimulus.electrodes.activeCount == 1) { "a firmware stimulus is one electrode without grains" }
            return FirmwareStimulus(stimulus.electrodes.bits.countTrailingZeroBits(), stimulus.steps.single(), stimulus.durationMillis)
        }
    }
}

/**
 * Encodes a STIMULATE command for [stimulus] (checked here; the device checks it again and NACKs with OUT_OF_RANGE
 * and grains.h's reason as detail: 5 a step past 200, 8 an electrode past 8, 9 a duration outside 1..1000 ms) into
 * [destination] at [offset]; returns the encoded length.
 */
public fun FramedEncoder.stimulate(stimulus: FirmwareStimulus, destination: ByteArray, offset: Int = 0): Int =
    stimulatePayload(stimulus.payload(), destination, offset)
