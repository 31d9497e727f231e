package org.hapticon.sensor.grains

import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.protocol.framed.ChannelUnit

/**
 * The force range the firmware bins its grains over ([FirmwareGrainParams.minForce]..[FirmwareGrainParams.maxForce]),
 * in the force channel's own units. A slow press from [min] to [max] crosses every bin edge once, so the requested
 * number of grains fires only when this is the range the sensor actually spans: a 12-bit board binned over a
 * 10-bit 0..1023 fires all its grains in the first quarter of a press, a 10-bit board binned over 0..4095 only a
 * quarter of them.
 */
public data class FirmwareForceRange(val min: Int, val max: Int) {
    init {
        require(min in 0..0xFFFF && max in 0..0xFFFF && min < max) { "need 0 <= min < max <= 65535, were $min and $max" }
    }

    public companion object {
        /** The reference firmware's force channel (`HFP_GRAIN_CHANNEL` in hapticon_ref.ino). */
        public const val GRAIN_CHANNEL: Int = 0

        /** Raw counts of an [adcBits]-bit ADC: 0..2^adcBits − 1. */
        public fun ofAdcBits(adcBits: Int): FirmwareForceRange {
            require(adcBits in 1..16) { "adcBits must be in 1..16, was $adcBits" }
            return FirmwareForceRange(0, (1 shl adcBits) - 1)
        }

        /**
         * The range a framed board announced for [channel] in its device info: its ADC's full scale when the channel
         * carries raw counts. Null when the stream has no device info or the channel is in physical units (grams,
         * millinewtons, …), whose full scale the board does not announce.
         */
        public fun fromStream(info: StreamInfo?, channel: Int = GRAIN_CHANNEL): FirmwareForceRange? {
            val bits = info?.adcBits ?: return null
            return if (info.channelUnits?.getOrNull(channel) == ChannelUnit.RAW) ofAdcBits(bits) else null
        }
    }
}
