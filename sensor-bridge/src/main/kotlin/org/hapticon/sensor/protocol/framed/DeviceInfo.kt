package org.hapticon.sensor.protocol.framed

/**
 * What a device says about itself in its device-info frame, sent at boot and on request.
 *
 * @property firmwareMajor firmware version, major part (0..255).
 * @property firmwareMinor firmware version, minor part (0..255).
 * @property firmwarePatch firmware version, patch part (0..255).
 * @property adcBits ADC resolution of [ChannelUnit.RAW] channels (1..16).
 * @property sampleRateHz sample frames per second.
 * @property outputCount servo/PWM outputs, 0..[FramedProtocol.MAX_OUTPUTS].
 * @property channelUnits one unit per channel; its size is the channel count, 1..[FramedProtocol.MAX_CHANNELS].
 * @property name printable ASCII, at most [FramedProtocol.MAX_NAME_LENGTH] characters.
 * @throws IllegalArgumentException if a value is outside the range given above.
 */
public data class DeviceInfo(
    public val firmwareMajor: Int,
    public val firmwareMinor: Int,
    public val firmwarePatch: Int,
    public val adcBits: Int,
    public val sampleRateHz: Int,
    public val outputCount: Int,
    public val channelUnits: List<ChannelUnit>,
    public val name: String,
) {
    init {
        require(firmwareMajor in 0..255 && firmwareMinor in 0..255 && firmwarePatch in 0..255) { "firmware version parts must be in 0..255" }
        require(adcBits in 1..16) { "adcBits must be in 1..16, was $adcBits" }
        require(sampleRateHz >= 1) { "sampleRateHz must be positive, was $sampleRateHz" }
        require(outputCount in 0..FramedProtocol.MAX_OUTPUTS) { "outputCount must be in 0..${FramedProtocol.MAX_OUTPUTS}, was $outputCount" }
        require(channelUnits.size in 1..FramedProtocol.MAX_CHANNELS) { "need 1..${FramedProtocol.MAX_CHANNELS} channels, got ${channelUnits.size}" }
        require(name.length <= FramedProtocol.MAX_NAME_LENGTH && name.all { it in ' '..'~' }) { "name must be at most ${FramedProtocol.MAX_NAME_LENGTH} printable ASCII characters" }
    }

    /** Number of analog channels in each sample frame. */
    public val channelCount: Int get() = channelUnits.size

    /** The firmware version as `major.minor.patch`. */
    public val firmwareVersion: String get() = "$firmwareMajor.$firmwareMinor.$firmwarePatch"
}
