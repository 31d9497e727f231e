package org.hapticon.sensor.grains

import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.electrotactile.ElectrodePattern
import org.hapticon.sensor.electrotactile.ElectrotactileCalibration
import org.hapticon.sensor.electrotactile.TimeDivisionScan
import org.hapticon.sensor.protocol.framed.FramedEncoder

/**
 * The compliance-grain parameters the reference firmware renders stand-alone (firmware/hapticon_ref/grains.h),
 * sent with the framed protocol's SET_GRAINS command ([setGrains]).
 *
 * [grainCount] grains (bins = grains + 1, as [GrainSettings]) over [minForce]..[maxForce] in the force channel's
 * own units (the board bins what it samples), [pattern] with at least 4 electrodes, each electrode's amplitude
 * step in [steps] (0..200, 200 = 2.7 mA), a low-pass at [cutoffHz] and [grainMicros] of dead time per grain: by
 * default the grain's own delivery ([TimeDivisionScan.deliveryMicros], 9–10.25 ms), since Shaping Compliance fires no
 * grain while one is being delivered (003_8ca1dc8f53472543.txt:97); a longer dead time may be asked for, never a
 * shorter one.
 * Checked here as the firmware checks it, so a refused update never reaches the wire.
 * @throws IllegalArgumentException (or [org.hapticon.sensor.safety.SafetyLimitException] for a step past 200) when any is out of range.
 */
public data class FirmwareGrainParams(
    val grainCount: Int,
    val distribution: BinDistribution,
    val minForce: Int,
    val maxForce: Int,
    val pattern: ElectrodePattern,
    val steps: List<Int>,
    val cutoffHz: Double = GrainSettings.DEFAULT_CUTOFF_HZ,
    val grainMicros: Int = TimeDivisionScan.deliveryMicros(pattern).toInt(),
) {
    init {
        require(grainCount in GrainSettings.MIN_GRAIN_COUNT..GrainSettings.MAX_GRAIN_COUNT) { "grain count must be in 0..99, was $grainCount" }
        require(minForce in 0..0xFFFF && maxForce in 0..0xFFFF && minForce < maxForce) { "need 0 <= minForce < maxForce <= 65535, were $minForce and $maxForce" }
        require(pattern.isStrongEnoughForCompliance) { "a compliance grain needs at least ${ElectrodePattern.MIN_COMPLIANCE_ELECTRODES} electrodes, $pattern has ${pattern.activeCount}" }
        require(steps.size == ElectrodePattern.SIZE * ElectrodePattern.SIZE) { "need 9 steps, got ${steps.size}" }
        steps.forEach { AmplitudeSteps.requireStep(it) }
        require(cutoffHz > 0.0 && cutoffHz * 10 <= 0xFFFF) { "cutoffHz must be in (0, 6553.5], was $cutoffHz" }
        val burst = TimeDivisionScan.deliveryMicros(pattern)
        require(grainMicros in burst..0xFFFF) { "grainMicros must be in $burst..65535 (no shorter than its own burst), was $grainMicros" }
    }

    /** The 21-byte SET_GRAINS payload, little-endian, in grains.h's order. */
    public fun payload(): ByteArray {
        val out = ByteArray(PAYLOAD_LENGTH)
        fun u16(at: Int, v: Int) {
            out[at] = v.toByte()
            out[at + 1] = (v ushr 8).toByte()
        }
        out[0] = grainCount.toByte()
        out[1] = distribution.ordinal.toByte()
        u16(2, minForce)
        u16(4, maxForce)
        u16(6, pattern.bits)
        steps.forEachIndexed { i, s -> out[8 + i] = s.toByte() }
        u16(17, Math.round(cutoffHz * 10).toInt())
        u16(19, grainMicros)
        return out
    }

    /** The range the board bins over. */
    public val forceRange: FirmwareForceRange get() = FirmwareForceRange(minForce, maxForce)

    /**
     * The settings under which sensor-bridge's [GrainDecider] decides as the board does (grains.cpp is its twin): the
     * same bins over the same range in the channel's units, filter and grain length. `replicate 003` runs a slow
     * press through it to show what the board fires.
     */
    public fun deciderSettings(): GrainSettings =
        GrainSettings(grainCount, distribution, minForce.toDouble(), maxForce.toDouble(), cutoffHz, grainMicros / 1e6)

    public companion object {
        /** Bytes of the payload. */
        public const val PAYLOAD_LENGTH: Int = 21

        /**
         * [grainCount] grains over the board's [range] ([FirmwareForceRange.fromStream]: what the sensor actually
         * spans, not an assumed 10-bit 0..1023) on [pattern] at the calibrated [steps].
         */
        public fun of(grainCount: Int, distribution: BinDistribution, range: FirmwareForceRange, pattern: ElectrodePattern, steps: List<Int>): FirmwareGrainParams =
            FirmwareGrainParams(grainCount, distribution, range.min, range.max, pattern, steps)

        /**
         * Shaping Compliance's whole-array check after the per-electrode calibration: [ElectrotactileCalibration.CHECK_GRAINS]
         * (39) grains, linear, over [range], all nine electrodes at their [steps].
         * @throws org.hapticon.sensor.safety.SafetyLimitException when a step is outside 0..200 (above 2.7 mA).
         */
        public fun wholeArrayCheck(steps: List<Int>, range: FirmwareForceRange): FirmwareGrainParams =
            of(ElectrotactileCalibration.CHECK_GRAINS, BinDistribution.LINEAR, range, ElectrodePattern.ALL, steps)
    }
}

/**
 * Encodes a SET_GRAINS command giving the firmware's stand-alone grain renderer [params] (checked here; the
 * device checks them again and NACKs with OUT_OF_RANGE and grains.h's reason as detail) into [destination]
 * at [offset]; returns the encoded length. An extension here rather than a member of [FramedEncoder], so the
 * protocol package does not depend on the grain model (docs/architecture.md).
 */
public fun FramedEncoder.setGrains(params: FirmwareGrainParams, destination: ByteArray, offset: Int = 0): Int =
    setGrainsPayload(params.payload(), destination, offset)
