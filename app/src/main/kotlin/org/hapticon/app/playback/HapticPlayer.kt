package org.hapticon.app.playback

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.platform.VibrationVerdict
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.Fidelity
import org.hapticon.core.render.RendererKind
import kotlin.coroutines.CoroutineContext
import kotlin.coroutines.EmptyCoroutineContext

/**
 * Plays haptic icons on the phone's actuator. Every play names the [VibrationUsage] it is (docs/messaging.md, "Android's
 * rules for vibrating"): Android decides by it whether the vibration plays, and a play Android would ignore returns
 * [Playback.Ignored] instead of vibrating.
 */
interface HapticPlayer {
    /** What the phone's vibrator can do. */
    val capabilities: PlaybackCapabilities

    /**
     * Starts playing [icon] as [usage] with the default envelope model ([EnvelopeModel.DEFAULT], what the study's
     * participants felt), replacing whatever is playing. Returns how it is played, [Playback.Unsupported] when the
     * phone has no vibrator, or [Playback.Ignored] when Android would not play it now. Renders the icon on the calling
     * thread (and may write its audio file), so callers use [playOffMain], which runs this in [renderContext]; rendering
     * on the main thread is a StrictMode violation in debug builds.
     */
    fun play(icon: HapticIcon, usage: VibrationUsage): Playback

    /** Where [playOffMain] renders: the real players' default is `Dispatchers.Default`; doubles that do not render stay on the caller's. */
    val renderContext: CoroutineContext get() = EmptyCoroutineContext

    /**
     * Starts playing [icon] with its envelope shaped by [model] (a study protocol's `envelopeModel`), as
     * [play] does. A player that renders envelopes ([AdaptiveHapticPlayer]) overrides this; a player that
     * cannot render another model plays the default one only and returns [Playback.Unsupported] for any other, so nothing is ever played under the wrong model.
     */
    fun play(icon: HapticIcon, model: EnvelopeModel, usage: VibrationUsage): Playback =
        if (model == EnvelopeModel.DEFAULT) play(icon, usage) else Playback.Unsupported

    /**
     * Starts playing [pattern] (an imported AHAP or `.haptic`, a pattern message) as [usage], replacing whatever is
     * playing, within the same safety limits as icons. Returns how it is played, [Playback.Unsupported] or
     * [Playback.Ignored]. Never blocks.
     */
    fun play(pattern: HapticPattern, usage: VibrationUsage): Playback

    /** What Android would do now with a vibration of [usage] from this player (by the route it would fall back to). */
    fun verdict(usage: VibrationUsage): VibrationVerdict

    /** Stops any vibration this player started. */
    fun stop()
}

/** The vibrator features that decide how faithfully an icon can be played. */
data class PlaybackCapabilities(
    val hasVibrator: Boolean,
    val hasAmplitudeControl: Boolean,
    val apiLevel: Int,
) {
    /** The renderer this phone gets: amplitude steps when it can vary strength, else on/off. */
    val renderer: RendererKind
        get() = when {
            !hasVibrator -> RendererKind.NONE
            hasAmplitudeControl -> RendererKind.AMPLITUDE_WAVEFORM
            else -> RendererKind.ON_OFF
        }
}

/** The outcome of [HapticPlayer.play]. */
sealed interface Playback {
    /** Playing with [renderer] for [durationMillis]; [fidelity] compares it with the ideal envelope. */
    data class Playing(val renderer: RendererKind, val durationMillis: Long, val fidelity: Fidelity) : Playback

    /** Nothing plays: the phone has no vibrator, or this player cannot render the envelope model asked for. */
    data object Unsupported : Playback

    /** Nothing plays: Android would ignore the vibration now, for the reason [verdict] gives (the app in the background, …). */
    data class Ignored(val verdict: VibrationVerdict) : Playback
}
