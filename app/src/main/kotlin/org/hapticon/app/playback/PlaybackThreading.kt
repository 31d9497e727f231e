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
 * Marks rendering work for StrictMode (`StrictMode.noteSlowCall`): with `detectCustomSlowCalls()`, as the
 * debug build's policy ([org.hapticon.app.HapticonApplication]) and `MainThreadWorkTest` set it, rendering
 * on a thread with that policy (the main thread) is a violation. A no-op elsewhere and in release builds.
 */
internal fun noteRendering(what: String) = StrictMode.noteSlowCall(what)

/** The context players render in by default: the shared pool for CPU work. */
internal val DefaultRenderContext: CoroutineContext get() = kotlinx.coroutines.Dispatchers.Default
