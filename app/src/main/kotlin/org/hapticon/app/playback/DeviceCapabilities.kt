package org.hapticon.app.playback

import android.content.Context
import android.media.AudioManager
import android.os.Build
import android.os.Vibrator
import org.hapticon.core.pattern.EnvelopeEffectInfo

/** Everything about a phone that decides how it plays an icon; read once by [detect]. */
data class DeviceCapabilities(
    val hasVibrator: Boolean,
    val hasAmplitudeControl: Boolean,
    val apiLevel: Int,
    /** API 34+ `Vibrator.getResonantFrequency()`, null when unknown (NaN) or older. */
    val resonantFrequencyHz: Double? = null,
    /** API 36+ `Vibrator.areEnvelopeEffectsSupported()`. */
    val envelopeEffectsSupported: Boolean = false,
    /** API 31+ `AudioManager.isHapticPlaybackSupported()`: audio streams can carry a haptic channel. */
    val hapticPlaybackSupported: Boolean = false,
    /** API 31+ `HapticGenerator.isAvailable()`: the platform can derive the haptic channel from audio. */
    val hapticGeneratorAvailable: Boolean = false,
    /**
     * API 36+ `Vibrator.getFrequencyProfile()` min..max Hz: the frequencies `WaveformEnvelopeBuilder` may use.
     * Null when the phone has no frequency control (no profile, or a NaN or empty range).
     */
    val frequencyRangeHz: ClosedFloatingPointRange<Double>? = null,
    /** API 36+ `Vibrator.getEnvelopeEffectInfo()`, null without envelope effects. */
    val envelopeInfo: EnvelopeEffectInfo? = null,
) {
    companion object {
        /**
         * Reads the capabilities of [vibrator], guarding each API-specific call by SDK level. The audio
         * flags are asked for unless given ([hapticPlayback], [hapticGenerator]: known from an earlier call).
         */
        fun detect(
            context: Context,
            vibrator: Vibrator,
            hapticPlayback: Boolean? = null,
            hapticGenerator: Boolean? = null,
        ): DeviceCapabilities {
            val api = Build.VERSION.SDK_INT
            val resonant = if (api >= 34) vibrator.resonantFrequency.toDouble().takeIf { it.isFinite() && it > 0 } else null
            return DeviceCapabilities(
                hasVibrator = vibrator.hasVibrator(),
                hasAmplitudeControl = vibrator.hasAmplitudeControl(),
                apiLevel = api,
                resonantFrequencyHz = resonant,
                envelopeEffectsSupported = api >= 36 && vibrator.areEnvelopeEffectsSupported(),
                hapticPlaybackSupported = hapticPlayback ?: (api >= 31 && AudioManager.isHapticPlaybackSupported()),
                // Some builds lack the effect library; asking must not take the app down.
                hapticGeneratorAvailable = hapticGenerator
                    ?: (api >= 31 && runCatching { android.media.audiofx.HapticGenerator.isAvailable() }.getOrDefault(false)),
                frequencyRangeHz = if (api >= 36) frequencyRangeOf(vibrator) else null,
                envelopeInfo = if (api >= 36 && vibrator.areEnvelopeEffectsSupported()) envelopeInfoOf(vibrator) else null,
            )
        }
    }
}

@androidx.annotation.RequiresApi(36)
private fun frequencyRangeOf(vibrator: Vibrator): ClosedFloatingPointRange<Double>? {
    val profile = vibrator.frequencyProfile ?: return null
    val min = profile.minFrequencyHz.toDouble()
    val max = profile.maxFrequencyHz.toDouble()
    return if (min.isFinite() && max.isFinite() && min > 0 && max > min) min..max else null
}

@androidx.annotation.RequiresApi(36)
private fun envelopeInfoOf(vibrator: Vibrator): EnvelopeEffectInfo? {
    val info = vibrator.envelopeEffectInfo ?: return null
    return EnvelopeEffectInfo(info.maxSize, info.minControlPointDurationMillis, info.maxControlPointDurationMillis, info.maxDurationMillis)
        .takeIf { it.maxControlPoints > 0 && it.minControlPointMillis > 0 }
}
