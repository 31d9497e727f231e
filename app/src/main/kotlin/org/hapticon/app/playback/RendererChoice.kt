package org.hapticon.app.playback

import android.content.Context
import android.media.AudioManager
import android.os.Build
import android.os.VibrationEffect
import android.os.Vibrator
import kotlin.math.roundToInt
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeControlPoints
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.RendererKind

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
) {
    companion object {
        /** Reads the capabilities of [vibrator], guarding each API-specific call by SDK level. */
        fun detect(context: Context, vibrator: Vibrator): DeviceCapabilities {
            val api = Build.VERSION.SDK_INT
            val resonant = if (api >= 34) vibrator.resonantFrequency.toDouble().takeIf { it.isFinite() && it > 0 } else null
            return DeviceCapabilities(
                hasVibrator = vibrator.hasVibrator(),
                hasAmplitudeControl = vibrator.hasAmplitudeControl(),
                apiLevel = api,
                resonantFrequencyHz = resonant,
                envelopeEffectsSupported = api >= 36 && vibrator.areEnvelopeEffectsSupported(),
                hapticPlaybackSupported = api >= 31 && AudioManager.isHapticPlaybackSupported(),
            )
        }
    }
}

/** How an icon reaches the actuator, best first. */
enum class AdaptiveRenderer(val label: String) {
    /** PCM with a haptic channel played through the audio path (the icon's own carrier). */
    AUDIO_COUPLED("audio-coupled haptics"),

    /** API 36 envelope effect: amplitude and frequency control points, played smoothly by the vibrator HAL. */
    ENVELOPE("envelope effect"),
    AMPLITUDE_WAVEFORM("amplitude waveform"),
    ON_OFF("on/off pattern"),
    NONE("no vibrator"),
}

/**
 * Picks the renderer for an icon on a phone: audio-coupled haptics where the phone and this build
 * support it, else the API 36 envelope when the icon's envelope is representable in control points,
 * else amplitude steps, else on/off. A user [override] wins when the phone can do it; otherwise the
 * automatic choice stands (forcing an impossible renderer would play nothing).
 */
object RendererChoice {
    /**
     * Whether this build can render audio-coupled haptics. False: the public API plays a haptic channel only
     * from a media file carrying one (OGG with ANDROID_HAPTIC), and the AudioTrack haptic channel masks are
     * system API; encoding such a file at runtime is not in this build yet.
     */
    const val AUDIO_COUPLED_IMPLEMENTED = false

    fun possible(device: DeviceCapabilities, icon: HapticIcon?): List<AdaptiveRenderer> = buildList {
        if (!device.hasVibrator) return@buildList
        if (AUDIO_COUPLED_IMPLEMENTED && device.hapticPlaybackSupported) add(AdaptiveRenderer.AUDIO_COUPLED)
        if (device.apiLevel >= 36 && device.envelopeEffectsSupported && (icon == null || envelopeRepresentable(icon))) add(AdaptiveRenderer.ENVELOPE)
        if (device.hasAmplitudeControl) add(AdaptiveRenderer.AMPLITUDE_WAVEFORM)
        add(AdaptiveRenderer.ON_OFF)
    }

    fun choose(device: DeviceCapabilities, icon: HapticIcon?, override: AdaptiveRenderer? = null): AdaptiveRenderer {
        val options = possible(device, icon)
        if (options.isEmpty()) return AdaptiveRenderer.NONE
        return if (override != null && override in options) override else options.first()
    }

    private fun envelopeRepresentable(icon: HapticIcon): Boolean =
        runCatching { EnvelopeControlPoints.render(icon).isRepresentable }.getOrDefault(false)

    /**
     * How faithfully [renderer] plays [icon], 0..100 (100 = the ideal envelope): 100 minus the renderer's
     * RMS error in percent of full scale. Null when nothing plays.
     */
    fun fidelityPercent(renderer: AdaptiveRenderer, icon: HapticIcon): Int? {
        val rms = when (renderer) {
            AdaptiveRenderer.AUDIO_COUPLED -> 0.0
            AdaptiveRenderer.ENVELOPE -> EnvelopeControlPoints.render(icon).fidelity.rmsError
            AdaptiveRenderer.AMPLITUDE_WAVEFORM -> VibrationWaveform.render(icon).fidelity.rmsError
            AdaptiveRenderer.ON_OFF -> VibrationWaveform.onOff(icon).fidelity.rmsError
            AdaptiveRenderer.NONE -> return null
        }
        return ((1.0 - rms).coerceIn(0.0, 1.0) * 100).roundToInt()
    }

    /** The renderer a peer announced, in this app's terms. */
    fun fromWire(kind: RendererKind): AdaptiveRenderer = when (kind) {
        RendererKind.AMPLITUDE_WAVEFORM -> AdaptiveRenderer.AMPLITUDE_WAVEFORM
        RendererKind.ON_OFF -> AdaptiveRenderer.ON_OFF
        RendererKind.AUDIO -> AdaptiveRenderer.AUDIO_COUPLED
        RendererKind.NONE, RendererKind.UNKNOWN -> AdaptiveRenderer.NONE
    }

    /**
     * The wire name of [renderer]. The messaging protocol has no value for the envelope renderer yet, so an
     * envelope phone announces amplitude-waveform (what it falls back to for icons the envelope cannot carry).
     */
    fun toWire(renderer: AdaptiveRenderer): RendererKind = when (renderer) {
        AdaptiveRenderer.AUDIO_COUPLED -> RendererKind.AUDIO
        AdaptiveRenderer.ENVELOPE, AdaptiveRenderer.AMPLITUDE_WAVEFORM -> RendererKind.AMPLITUDE_WAVEFORM
        AdaptiveRenderer.ON_OFF -> RendererKind.ON_OFF
        AdaptiveRenderer.NONE -> RendererKind.NONE
    }

    /** This device's capabilities message for [user]. */
    fun capabilitiesOf(user: String, device: DeviceCapabilities, override: AdaptiveRenderer?): Capabilities = Capabilities(
        user = user,
        renderer = toWire(choose(device, null, override)),
        amplitudeControl = device.hasAmplitudeControl,
        apiLevel = device.apiLevel,
        resonantFrequencyHz = device.resonantFrequencyHz,
    )
}

/**
 * Plays icons with the renderer [RendererChoice] picks for this phone and the user's override. The
 * envelope path is API 36 only; every other path is the step waveform of [VibrationWaveform].
 */
class AdaptiveHapticPlayer(
    private val vibrator: Vibrator,
    private val device: () -> DeviceCapabilities,
    private val override: () -> AdaptiveRenderer?,
) : HapticPlayer {
    override val capabilities: PlaybackCapabilities
        get() = device().let { PlaybackCapabilities(it.hasVibrator, it.hasAmplitudeControl, it.apiLevel) }

    /** The renderer [icon] would get now. */
    fun rendererFor(icon: HapticIcon): AdaptiveRenderer = RendererChoice.choose(device(), icon, override())

    override fun play(icon: HapticIcon): Playback {
        val waveform = when (rendererFor(icon)) {
            AdaptiveRenderer.NONE -> return Playback.Unsupported
            AdaptiveRenderer.ENVELOPE -> if (Build.VERSION.SDK_INT >= 36) {
                val points = EnvelopeControlPoints.render(icon)
                vibrator.vibrate(points.toEnvelopeEffect())
                return Playback.Playing(Renderer.AMPLITUDE_WAVEFORM, points.totalMillis, points.fidelity)
            } else {
                VibrationWaveform.render(icon)
            }
            // Audio-coupled is never chosen while AUDIO_COUPLED_IMPLEMENTED is false.
            AdaptiveRenderer.AUDIO_COUPLED, AdaptiveRenderer.AMPLITUDE_WAVEFORM -> VibrationWaveform.render(icon)
            AdaptiveRenderer.ON_OFF -> VibrationWaveform.onOff(icon)
        }
        vibrator.vibrate(waveform.toVibrationEffect())
        val renderer = if (waveform.amplitudes().all { it == 0 || it == VibrationWaveform.MAX_AMPLITUDE }) Renderer.ON_OFF else Renderer.AMPLITUDE_WAVEFORM
        return Playback.Playing(renderer, waveform.totalMillis, waveform.fidelity)
    }

    override fun stop() = vibrator.cancel()
}

/**
 * The API 36 envelope effect of these control points. The basic builder (intensity and sharpness) is used
 * rather than the waveform builder (absolute Hz) because a point outside the actuator's frequency range
 * makes the waveform builder's effect fail on the device; the icon's carrier is mapped to a mid sharpness.
 */
@androidx.annotation.RequiresApi(36)
fun EnvelopeControlPoints.toEnvelopeEffect(): VibrationEffect {
    val builder = VibrationEffect.BasicEnvelopeBuilder().setInitialSharpness(ENVELOPE_SHARPNESS)
    for (point in points) builder.addControlPoint(point.amplitude.toFloat().coerceIn(0f, 1f), ENVELOPE_SHARPNESS, point.durationMillis)
    return builder.build()
}

private const val ENVELOPE_SHARPNESS = 0.5f
