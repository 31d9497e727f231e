package org.hapticon.app.playback

import android.os.StrictMode
import kotlin.coroutines.CoroutineContext
import kotlinx.coroutines.withContext
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.render.EnvelopeModel

/**
 * Plays [icon] with the rendering done in [HapticPlayer.renderContext], never on the caller's thread: a press
 * on the main thread suspends instead of rendering there (tens of ms for a long icon, plus writing its audio
 * file for audio-coupled haptics). This is how screens and services play icons.
 */
suspend fun HapticPlayer.playOffMain(icon: HapticIcon): Playback = withContext(renderContext) { play(icon) }

/** [HapticPlayer.play] of [icon] under envelope [model] (a study protocol's), rendered off the caller's thread like [playOffMain]. */
suspend fun HapticPlayer.playOffMain(icon: HapticIcon, model: EnvelopeModel): Playback = withContext(renderContext) { play(icon, model) }

/** [HapticPlayer.play] of [pattern], its control points or waveform computed off the caller's thread like [playOffMain]. */
suspend fun HapticPlayer.playOffMain(pattern: HapticPattern): Playback = withContext(renderContext) { play(pattern) }

/**
 * Plays what a message carries, off the caller's thread like [playOffMain]: its [icon], else its [pattern] (a
 * message carries at most one, as `ChatMessage` requires); null, with nothing played, when it carries neither.
 * The one place that choice is made for a press on a bubble (`ConversationViewModel.feel`) and for auto-play on
 * arrival (`ChatSync`).
 */
suspend fun HapticPlayer.playMessageOffMain(icon: HapticIcon?, pattern: HapticPattern?): Playback? = when {
    icon != null -> playOffMain(icon)
    pattern != null -> playOffMain(pattern)
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
