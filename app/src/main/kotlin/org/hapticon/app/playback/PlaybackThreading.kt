package org.hapticon.app.playback

import android.os.StrictMode
import kotlin.coroutines.CoroutineContext
import kotlinx.coroutines.withContext
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.EnvelopeModel

/**
 * Plays [icon] as [usage] with the rendering done in [HapticPlayer.renderContext], never on the caller's thread: a
 * press on the main thread suspends instead of rendering there (tens of ms for a long icon, plus writing its audio
 * file for audio-coupled haptics). This is how screens and services play icons.
 */
suspend fun HapticPlayer.playOffMain(icon: HapticIcon, usage: VibrationUsage): Playback = withContext(renderContext) { play(icon, usage) }

/** [HapticPlayer.play] of [icon] under envelope [model] (a study protocol's), rendered off the caller's thread like [playOffMain]. */
suspend fun HapticPlayer.playOffMain(icon: HapticIcon, model: EnvelopeModel, usage: VibrationUsage): Playback =
    withContext(renderContext) { play(icon, model, usage) }

/** [HapticPlayer.play] of [pattern], its control points or waveform computed off the caller's thread like [playOffMain]. */
suspend fun HapticPlayer.playOffMain(pattern: HapticPattern, usage: VibrationUsage): Playback = withContext(renderContext) { play(pattern, usage) }

/**
 * The usage of playing a message's icon or pattern. A received one is the peer reaching the user, however it is played
 * (on arrival, "Feel again" in its notification, a press on its bubble): `USAGE_COMMUNICATION_REQUEST`, which Android
 * plays from the background and in Battery Saver and which the touch feedback switch does not silence, so the felt
 * receipt that follows it holds wherever it was played. An own message pressed in the open app is a touch.
 */
fun messageUsage(outgoing: Boolean): VibrationUsage = if (outgoing) VibrationUsage.TOUCH else VibrationUsage.COMMUNICATION_REQUEST

/**
 * Plays what a message carries as [usage], off the caller's thread like [playOffMain]: its [icon], else its [pattern]
 * (a message carries at most one, as `ChatMessage` requires); null, with nothing played, when it carries neither.
 * The one place that choice is made for a press on a bubble (`ConversationViewModel.feel`), "Feel again" and auto-play
 * on arrival (`ChatSync`).
 */
suspend fun HapticPlayer.playMessageOffMain(icon: HapticIcon?, pattern: HapticPattern?, usage: VibrationUsage): Playback? = when {
    icon != null -> playOffMain(icon, usage)
    pattern != null -> playOffMain(pattern, usage)
    else -> null
}

/**
 * Marks rendering work for StrictMode (`StrictMode.noteSlowCall`): with `detectCustomSlowCalls()`, as the
 * debug build's policy ([org.hapticon.app.HapticonApplication]) and `MainThreadWorkTest` set it, rendering
 * on a thread with that policy (the main thread) is a violation. A no-op elsewhere and in release builds.
 */
internal fun noteRendering(what: String) = StrictMode.noteSlowCall(what)

/** The context players render in by default: the shared pool for CPU work. */
internal val DefaultRenderContext: CoroutineContext get() = kotlinx.coroutines.Dispatchers.Default
