package org.hapticon.app.playback

import android.os.Build
import android.util.Log
import java.io.IOException
import kotlin.coroutines.CoroutineContext
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternEnvelope
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.pattern.toPattern
import org.hapticon.core.platform.VibrationRoute
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.platform.VibrationVerdict
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.PcmRenderer
import org.hapticon.core.render.VibrationWaveform
import org.hapticon.core.render.RendererKind

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
