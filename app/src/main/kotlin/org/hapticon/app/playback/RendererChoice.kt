package org.hapticon.app.playback

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.render.EnvelopeControlPoints
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.PcmRenderer
import org.hapticon.core.render.RendererKind
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.messaging.Capabilities
import kotlin.math.roundToInt

/**
 * What people read for a renderer. The app, the settings and the wire share one type,
 * [RendererKind] (haptics-core; messaging maps it to its wire name), so a peer's announced renderer and the local choice compare directly.
 */
val RendererKind.label: String
    get() = when (this) {
        RendererKind.AUDIO_COUPLED -> "audio-coupled haptics"
        RendererKind.ENVELOPE -> "envelope effect"
        RendererKind.AMPLITUDE_WAVEFORM -> "amplitude waveform"
        RendererKind.ON_OFF -> "on/off pattern"
        RendererKind.AUDIO -> "audio (no vibrator)"
        RendererKind.NONE -> "no vibrator"
        RendererKind.UNKNOWN -> "a renderer this version does not know"
    }

/**
 * Picks the renderer for an icon on a phone: audio-coupled haptics where the phone and this build
 * support it, else the API 36 envelope when the icon's envelope is representable in control points,
 * else amplitude steps, else on/off. A user [override] wins when the phone can do it; otherwise the
 * automatic choice stands (forcing an impossible renderer would play nothing).
 */
object RendererChoice {
    fun possible(device: DeviceCapabilities, icon: HapticIcon?, model: EnvelopeModel = EnvelopeModel.DEFAULT): List<RendererKind> = buildList {
        if (!device.hasVibrator) return@buildList
        if (device.apiLevel >= 31 && device.hapticPlaybackSupported && device.hapticGeneratorAvailable) add(RendererKind.AUDIO_COUPLED)
        if (device.apiLevel >= 36 && device.envelopeEffectsSupported && (icon == null || envelopeRepresentable(icon, model))) add(RendererKind.ENVELOPE)
        if (device.hasAmplitudeControl) add(RendererKind.AMPLITUDE_WAVEFORM)
        add(RendererKind.ON_OFF)
    }

    fun choose(device: DeviceCapabilities, icon: HapticIcon?, override: RendererKind? = null, model: EnvelopeModel = EnvelopeModel.DEFAULT): RendererKind {
        val options = possible(device, icon, model)
        if (options.isEmpty()) return RendererKind.NONE
        return if (override != null && override in options) override else options.first()
    }

    private fun envelopeRepresentable(icon: HapticIcon, model: EnvelopeModel): Boolean =
        runCatching { EnvelopeControlPoints.fit(icon, model).isRepresentable }.getOrDefault(false)

    /**
     * How faithfully [renderer] plays [icon], 0..100 (100 = the ideal envelope): 100 minus the renderer's
     * RMS error in percent of full scale (for audio-coupled haptics, the PCM16 rendering's against the ideal
     * signal: the audio path carries the icon sample by sample). Null when nothing plays.
     */
    fun fidelityPercent(renderer: RendererKind, icon: HapticIcon): Int? {
        noteRendering("fidelity of ${icon.name}")
        val rms = when (renderer) {
            RendererKind.AUDIO_COUPLED, RendererKind.AUDIO -> PcmRenderer(icon, IconAudioCache.SAMPLE_RATE).fidelity().rmsError
            RendererKind.ENVELOPE -> EnvelopeControlPoints.fit(icon).fidelity.rmsError
            RendererKind.AMPLITUDE_WAVEFORM -> VibrationWaveform.amplitudeSteps(icon).fidelity.rmsError
            RendererKind.ON_OFF -> VibrationWaveform.onOff(icon).fidelity.rmsError
            RendererKind.NONE, RendererKind.UNKNOWN -> return null
        }
        return ((1.0 - rms).coerceIn(0.0, 1.0) * 100).roundToInt()
    }

    /**
     * This device's capabilities message for [user]: with the envelope support, frequency profile and [pitchFit]
     * a sender needs to tell which pitch this phone will play ([org.hapticon.app.feature.chat.PeerFeel]). A profile
     * outside what the wire accepts (1..2000 Hz) is left out rather than refused, so the rest is still published; so
     * are envelope limits outside the wire's bounds (the sender then assumes the guaranteed ones).
     */
    fun capabilitiesOf(user: String, device: DeviceCapabilities, override: RendererKind?, pitchFit: PitchFit = PitchFit.OCTAVES): Capabilities {
        val envelope = device.apiLevel >= 36 && device.envelopeEffectsSupported && device.envelopeInfo != null
        return Capabilities(
            user = user,
            renderer = choose(device, null, override),
            amplitudeControl = device.hasAmplitudeControl,
            apiLevel = device.apiLevel,
            resonantFrequencyHz = device.resonantFrequencyHz?.takeIf { it in 1.0..Capabilities.MAX_RESONANT_FREQUENCY_HZ },
            envelopeEffects = envelope,
            frequencyRangeHz = device.frequencyRangeHz?.takeIf { it.start >= 1.0 && it.endInclusive <= Capabilities.MAX_RESONANT_FREQUENCY_HZ },
            pitchFit = pitchFit,
            // The vibrator's own VibratorEnvelopeEffectInfo, so that a sender resamples exactly as this phone will.
            envelopeLimits = device.envelopeInfo?.takeIf { envelope && publishable(it) },
        )
    }

    // The bounds Capabilities checks (messaging), as a test rather than an exception.
    private fun publishable(info: EnvelopeEffectInfo): Boolean =
        info.maxControlPoints in 1..Capabilities.MAX_ENVELOPE_CONTROL_POINTS && info.minControlPointMillis >= 1 &&
            info.minControlPointMillis <= info.maxControlPointMillis && info.maxControlPointMillis <= info.maxDurationMillis &&
            info.maxDurationMillis <= Capabilities.MAX_ENVELOPE_MILLIS
}
