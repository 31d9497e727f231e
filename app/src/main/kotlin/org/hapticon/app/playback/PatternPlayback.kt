package org.hapticon.app.playback

import android.os.VibrationEffect
import androidx.annotation.RequiresApi
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternEnvelope
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.pattern.onOffWaveform
import org.hapticon.core.pattern.vibrationWaveform
import org.hapticon.core.render.RendererKind
import org.hapticon.core.render.VibrationWaveform

/**
 * How a phone plays a haptic pattern, decided by [PatternPlan.of] from its [DeviceCapabilities]:
 * - API 36 with envelope effects: [Envelope], the pattern as control points within the vibrator's
 *   `VibratorEnvelopeEffectInfo`; with Hz (`WaveformEnvelopeBuilder`) where `getFrequencyProfile()` reports a
 *   range, moved into it by octaves or clamped ([PitchFit], a user choice), else with sharpness
 *   (`BasicEnvelopeBuilder`) mapped from the frequency;
 * - otherwise, or when the envelope cannot follow the pattern (pulses shorter than a control point): [Steps],
 *   amplitude steps (`createWaveform`) where the vibrator has amplitude control, on/off steps otherwise.
 *   These lose the frequency curve: the vibrator plays at its own resonance.
 * - audio-coupled haptics first where the phone has them ([AudioCoupled]): the pattern rendered as audio
 *   (`pattern.signal()`, its own frequencies sample by sample) with the haptic channel on, as icons are.
 */
sealed interface PatternPlan {
    /** The renderer this plan uses, as the wire and the settings name it. */
    val renderer: RendererKind

    /** One line for the user: how this phone plays the pattern. */
    val summary: String

    /** An API 36 envelope effect. */
    data class Envelope(val envelope: PatternEnvelope) : PatternPlan {
        override val renderer: RendererKind get() = RendererKind.ENVELOPE
        override val summary: String
            get() = when (envelope) {
                is PatternEnvelope.Waveform -> "envelope effect with ${envelope.points.size} control points in Hz; ${envelope.pitch.summary}"
                is PatternEnvelope.Basic -> "envelope effect with ${envelope.points.size} control points; no frequency profile, so the pitch becomes sharpness"
            }
    }

    /** A step waveform: amplitude steps, or on/off when [renderer] is [RendererKind.ON_OFF]. */
    data class Steps(val waveform: VibrationWaveform, override val renderer: RendererKind) : PatternPlan {
        override val summary: String get() = "${renderer.label}, ${waveform.size} steps; the vibrator plays at its own pitch"
    }

    /**
     * Audio with the haptic channel on: the pattern's own signal at 48 kHz (`IconAudioCache.fileFor(pattern)`), so
     * its frequencies reach the actuator unchanged. The player falls back to [fallback] when the audio cannot be
     * rendered or the output is unavailable.
     */
    data class AudioCoupled(val fallback: PatternPlan) : PatternPlan {
        override val renderer: RendererKind get() = RendererKind.AUDIO_COUPLED
        override val summary: String get() = "audio-coupled haptics: the pattern as audio on the haptic channel, at its own pitch"
    }

    /** Nothing plays: no vibrator. */
    data object Silent : PatternPlan {
        override val renderer: RendererKind get() = RendererKind.NONE
        override val summary: String get() = "this phone has no vibrator"
    }

    companion object {
        /**
         * The plan for [pattern] on [device]; a user [override] of the renderer is honoured when the phone can do
         * it. Audio-coupled haptics come first where the phone has them (as for icons, [RendererChoice.possible]).
         */
        fun of(device: DeviceCapabilities, pattern: HapticPattern, override: RendererKind? = null, fit: PitchFit = PitchFit.OCTAVES): PatternPlan {
            if (!device.hasVibrator) return Silent
            val audio = device.apiLevel >= 31 && device.hapticPlaybackSupported && device.hapticGeneratorAvailable
            if (audio && (override == null || override == RendererKind.AUDIO_COUPLED)) {
                return AudioCoupled(vibrating(device, pattern, null, fit))
            }
            return vibrating(device, pattern, override, fit)
        }

        // The plan without audio: the envelope effect, else steps.
        private fun vibrating(device: DeviceCapabilities, pattern: HapticPattern, override: RendererKind?, fit: PitchFit): PatternPlan {
            val envelopeAllowed = override == null || override == RendererKind.ENVELOPE || override == RendererKind.AUDIO_COUPLED
            val info = device.envelopeInfo
            if (envelopeAllowed && device.apiLevel >= 36 && device.envelopeEffectsSupported && info != null) {
                PatternEnvelope.of(pattern, info, device.frequencyRangeHz, fit)?.let { return Envelope(it) }
            }
            return if (device.hasAmplitudeControl && override != RendererKind.ON_OFF) {
                Steps(pattern.vibrationWaveform(), RendererKind.AMPLITUDE_WAVEFORM)
            } else {
                Steps(pattern.onOffWaveform(), RendererKind.ON_OFF)
            }
        }
    }
}

/**
 * The platform effect of this envelope (API 36). Amplitudes are clamped to 0..1 and the total is checked
 * against the 30 s safety cap once more: this is the last step before the actuator.
 */
@RequiresApi(36)
fun PatternEnvelope.toVibrationEffect(): VibrationEffect {
    check(totalMillis in 1..(HapticIcon.MAX_DURATION_SECONDS * 1000).toLong()) { "envelope of $totalMillis ms is outside the safety cap" }
    return when (this) {
        is PatternEnvelope.Waveform -> VibrationEffect.WaveformEnvelopeBuilder().apply {
            setInitialFrequencyHz(initialHz.toFloat())
            for (point in points) addControlPoint(unit(point.amplitude), point.hertz.toFloat(), point.millis)
        }.build()
        is PatternEnvelope.Basic -> VibrationEffect.BasicEnvelopeBuilder().apply {
            setInitialSharpness(unit(initialSharpness))
            for (point in points) addControlPoint(unit(point.intensity), unit(point.sharpness), point.millis)
        }.build()
    }
}

private fun unit(x: Double): Float = x.toFloat().coerceIn(0f, 1f)
