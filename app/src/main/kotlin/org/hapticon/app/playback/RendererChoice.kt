package org.hapticon.app.playback

import android.content.Context
import android.media.AudioManager
import android.os.Build
import android.os.Vibrator
import android.util.Log
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternEnvelope
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.pattern.toPattern
import org.hapticon.core.platform.VibrationRoute
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.platform.VibrationVerdict
import org.hapticon.core.render.EnvelopeControlPoints
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.PcmRenderer
import org.hapticon.core.render.RendererKind
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.messaging.Capabilities
import java.io.IOException
import kotlin.coroutines.CoroutineContext
import kotlin.math.roundToInt

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

/**
 * Plays icons with the renderer [RendererChoice] picks for this phone and the user's override:
 * audio-coupled haptics through [audio] (the icon rendered by [audioCache]), the API 36 envelope, or the
 * step waveform of [VibrationWaveform]. If the audio path fails (the cache cannot be written) or Android would not let
 * its haptic channel play this usage now (a received icon's NOTIFICATION in Battery Saver), the icon plays on the
 * vibrator instead: a press is never silently lost. Every vibration carries the usage of its play ([UsageVibrator]).
 */
class AdaptiveHapticPlayer(
    private val vibrator: UsageVibrator,
    private val device: () -> DeviceCapabilities,
    private val override: () -> RendererKind?,
    private val audio: AudioCoupledOutput? = null,
    private val audioCache: IconAudioCache? = null,
    /** What to do with pattern frequencies the actuator cannot give (a user choice; octaves by default). */
    private val pitchFit: () -> PitchFit = { PitchFit.OCTAVES },
    override val renderContext: CoroutineContext = DefaultRenderContext,
) : HapticPlayer {
    override val capabilities: PlaybackCapabilities
        get() = device().let { PlaybackCapabilities(it.hasVibrator, it.hasAmplitudeControl, it.apiLevel) }

    /** The renderer [icon] (its envelope under [model]) would get now: audio-coupled only with an [audio] output that is available. */
    fun rendererFor(icon: HapticIcon, model: EnvelopeModel = EnvelopeModel.DEFAULT): RendererKind {
        val capabilities = device()
        val audioUsable = audio != null && audioCache != null && audio.isAvailable
        return RendererChoice.choose(if (audioUsable) capabilities else capabilities.copy(hapticGeneratorAvailable = false), icon, override(), model)
    }

    // The vibrator is every play's fallback, so what Android does with it is what this player can promise.
    override fun verdict(usage: VibrationUsage): VibrationVerdict = vibrator.verdict(usage)

    override fun play(icon: HapticIcon, usage: VibrationUsage): Playback = play(icon, EnvelopeModel.DEFAULT, usage)

    override fun play(icon: HapticIcon, model: EnvelopeModel, usage: VibrationUsage): Playback {
        noteRendering("render ${icon.name}")
        val waveform = when (rendererFor(icon, model)) {
            // choose() never returns the wire-only kinds AUDIO and UNKNOWN.
            RendererKind.NONE, RendererKind.AUDIO, RendererKind.UNKNOWN -> return Playback.Unsupported
            RendererKind.AUDIO_COUPLED -> playAudioCoupled(icon, model, usage)?.let { return it } ?: VibrationWaveform.amplitudeSteps(icon, model)
            RendererKind.ENVELOPE -> if (Build.VERSION.SDK_INT >= 36) {
                // The icon's note reaches the actuator as a pattern's does: Hz within the frequency profile (moved
                // by the user's pitch fit), else sharpness from the note; steps where the envelope cannot follow.
                val capabilities = device()
                val envelope = PatternEnvelope.of(
                    icon.toPattern(model), capabilities.envelopeInfo ?: EnvelopeEffectInfo.GUARANTEED,
                    capabilities.frequencyRangeHz, pitchFit(),
                )
                if (envelope != null) {
                    return vibrate(envelope.toVibrationEffect(), usage) { Playback.Playing(RendererKind.ENVELOPE, envelope.totalMillis, envelope.fidelity) }
                }
                VibrationWaveform.amplitudeSteps(icon, model)
            } else {
                VibrationWaveform.amplitudeSteps(icon, model)
            }
            RendererKind.AMPLITUDE_WAVEFORM -> VibrationWaveform.amplitudeSteps(icon, model)
            RendererKind.ON_OFF -> VibrationWaveform.onOff(icon, model)
        }
        val renderer = if (waveform.amplitudes().all { it == 0 || it == VibrationWaveform.MAX_AMPLITUDE }) RendererKind.ON_OFF else RendererKind.AMPLITUDE_WAVEFORM
        return vibrate(waveform.toVibrationEffect(), usage) { Playback.Playing(renderer, waveform.totalMillis, waveform.fidelity) }
    }

    /**
     * How [pattern] would play now: [PatternPlan.of] for this phone, the override and the pitch choice; audio-coupled
     * only with an [audio] output that is available, as for icons.
     */
    fun planFor(pattern: HapticPattern): PatternPlan {
        val capabilities = device()
        val audioUsable = audio != null && audioCache != null && audio.isAvailable
        return PatternPlan.of(if (audioUsable) capabilities else capabilities.copy(hapticGeneratorAvailable = false), pattern, override(), pitchFit())
    }

    override fun play(pattern: HapticPattern, usage: VibrationUsage): Playback {
        val planned = planFor(pattern)
        val vibrating = if (planned is PatternPlan.AudioCoupled) {
            playAudioCoupled(pattern, usage)?.let { return it }
            planned.fallback
        } else {
            planned
        }
        // The platform's own level decides, not the reported one: only a test's made-up capabilities differ.
        val plan = if (vibrating is PatternPlan.Envelope && Build.VERSION.SDK_INT < 36) stepsFor(pattern) else vibrating
        audio?.stop()
        return when (plan) {
            // A fallback is never audio-coupled again (PatternPlan.of plans it without audio).
            PatternPlan.Silent, is PatternPlan.AudioCoupled -> Playback.Unsupported
            is PatternPlan.Envelope -> vibrate(plan.envelope.toVibrationEffect(), usage) {
                Playback.Playing(RendererKind.ENVELOPE, plan.envelope.totalMillis, plan.envelope.fidelity)
            }
            is PatternPlan.Steps -> vibrate(plan.waveform.toVibrationEffect(), usage) {
                Playback.Playing(plan.renderer, plan.waveform.totalMillis, plan.waveform.fidelity)
            }
        }
    }

    private fun stepsFor(pattern: HapticPattern): PatternPlan =
        PatternPlan.of(device().copy(envelopeEffectsSupported = false, hapticGeneratorAvailable = false), pattern, override(), pitchFit())

    // Sends [effect] as [usage]: [playing] when Android plays it, else why not.
    private inline fun vibrate(effect: android.os.VibrationEffect, usage: VibrationUsage, playing: () -> Playback.Playing): Playback {
        val verdict = vibrator.vibrate(effect, usage)
        return if (verdict.plays) playing() else Playback.Ignored(verdict)
    }

    // The audio output, when Android lets its haptic channel play [usage] now; else the vibrator plays.
    private fun audioFor(usage: VibrationUsage, what: String): AudioCoupledOutput? {
        val output = audio ?: return null
        val verdict = vibrator.verdict(usage, VibrationRoute.AUDIO_HAPTIC_CHANNEL)
        if (!verdict.plays) {
            Log.i("AdaptiveHapticPlayer", "audio-coupled $what not played ($usage on the haptic channel: ${verdict.explanation}), vibrating instead")
            return null
        }
        return output
    }

    private fun playAudioCoupled(pattern: HapticPattern, usage: VibrationUsage): Playback? {
        val cache = audioCache ?: return null
        val output = audioFor(usage, pattern.name) ?: return null
        noteRendering("render ${pattern.name}")
        val (file, fidelity) = try {
            cache.fileFor(pattern) to cache.fidelityOf(pattern)
        } catch (e: IOException) {
            Log.w("AdaptiveHapticPlayer", "audio-coupled ${pattern.name} not rendered, vibrating instead: ${e.message}")
            return null
        } catch (e: IllegalArgumentException) {
            Log.w("AdaptiveHapticPlayer", "audio-coupled ${pattern.name} not renderable, vibrating instead: ${e.message}")
            return null
        }
        vibrator.cancel()
        output.play(file, usage)
        return Playback.Playing(RendererKind.AUDIO_COUPLED, Math.round(pattern.duration * 1000), fidelity)
    }

    override fun stop() {
        audio?.stop()
        vibrator.cancel()
    }

    private fun playAudioCoupled(icon: HapticIcon, model: EnvelopeModel, usage: VibrationUsage): Playback? {
        val cache = audioCache ?: return null
        val output = audioFor(usage, icon.name) ?: return null
        val file = try {
            cache.fileFor(icon, model)
        } catch (e: IOException) {
            Log.w("AdaptiveHapticPlayer", "audio-coupled ${icon.name} not rendered, vibrating instead: ${e.message}")
            return null
        }
        vibrator.cancel()
        output.play(file, usage)
        val samples = PcmRenderer(icon, cache.sampleRate, model).sampleCount
        return Playback.Playing(RendererKind.AUDIO_COUPLED, Math.round(samples * 1000.0 / cache.sampleRate), cache.fidelityOf(icon, model))
    }
}
