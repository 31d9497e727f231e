package org.hapticon.app.playback

import android.content.Context
import android.os.Build
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.platform.VibrationVerdict
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.RendererKind
import org.hapticon.core.render.VibrationWaveform
import kotlin.coroutines.CoroutineContext

/**
 * Plays icons through the phone's vibrator as `VibrationEffect.createWaveform` step waveforms rendered by
 * haptics-core ([VibrationWaveform]): amplitude steps where the vibrator supports amplitude
 * control, an on/off pattern otherwise; each with its usage ([UsageVibrator]). The tests' player of the step
 * waveforms alone; the app plays through [AdaptiveHapticPlayer], which also picks the other renderers.
 */
class VibratorHapticPlayer(
    private val vibrator: UsageVibrator,
    override val renderContext: CoroutineContext = DefaultRenderContext,
) : HapticPlayer {

    // Read at each use: cheap, and right even if the vibrator changes (e.g. an external one attaches).
    override val capabilities: PlaybackCapabilities
        get() = PlaybackCapabilities(
            hasVibrator = vibrator.hasVibrator(),
            hasAmplitudeControl = vibrator.hasAmplitudeControl(),
            apiLevel = Build.VERSION.SDK_INT,
        )

    override fun play(icon: HapticIcon, usage: VibrationUsage): Playback = play(icon, EnvelopeModel.DEFAULT, usage)

    override fun verdict(usage: VibrationUsage): VibrationVerdict = vibrator.verdict(usage)

    override fun play(icon: HapticIcon, model: EnvelopeModel, usage: VibrationUsage): Playback {
        noteRendering("render ${icon.name}")
        val renderer = capabilities.renderer
        val waveform = when (renderer) {
            RendererKind.AMPLITUDE_WAVEFORM -> VibrationWaveform.amplitudeSteps(icon, model)
            RendererKind.ON_OFF -> VibrationWaveform.onOff(icon, model)
            // PlaybackCapabilities.renderer never names these; only the adaptive player plays them.
            RendererKind.AUDIO_COUPLED, RendererKind.ENVELOPE -> VibrationWaveform.amplitudeSteps(icon, model)
            RendererKind.NONE, RendererKind.AUDIO, RendererKind.UNKNOWN -> return Playback.Unsupported
        }
        val verdict = vibrator.vibrate(waveform.toVibrationEffect(), usage)
        if (!verdict.plays) return Playback.Ignored(verdict)
        return Playback.Playing(renderer, waveform.totalMillis, waveform.fidelity)
    }

    /** [pattern] as amplitude steps, or on/off steps without amplitude control; the frequency curve is not played. */
    override fun play(pattern: HapticPattern, usage: VibrationUsage): Playback {
        val plan = PatternPlan.of(DeviceCapabilities(vibrator.hasVibrator(), vibrator.hasAmplitudeControl(), Build.VERSION.SDK_INT), pattern)
        val steps = plan as? PatternPlan.Steps ?: return Playback.Unsupported
        val verdict = vibrator.vibrate(steps.waveform.toVibrationEffect(), usage)
        if (!verdict.plays) return Playback.Ignored(verdict)
        return Playback.Playing(steps.renderer, steps.waveform.totalMillis, steps.waveform.fidelity)
    }

    override fun stop() = vibrator.cancel()

    companion object {
        /** A player on the phone's default vibrator. */
        fun create(context: Context): VibratorHapticPlayer = VibratorHapticPlayer(UsageVibrator.create(context))
    }
}
