package org.hapticon.app.playback

import android.content.Context
import android.net.Uri
import android.os.Handler
import android.os.Looper
import androidx.media3.common.MediaItem
import androidx.media3.exoplayer.ExoPlayer
import java.io.File

/**
 * One Media3 ExoPlayer for local audio files, made on first use with [configure] (attributes, audio session) and
 * touched only on the main thread, as ExoPlayer requires: calls from other threads are posted there.
 */
class MainThreadFilePlayer(private val context: Context, private val configure: (ExoPlayer) -> Unit) {
    private val main = Handler(Looper.getMainLooper())

    /** The player once made; main thread only. */
    var player: ExoPlayer? = null
        private set

    /** Plays [file] from its start, after [setup] (repeat mode, volume) on the player; replaces what plays. */
    fun play(file: File, setup: (ExoPlayer) -> Unit = {}) = onMain {
        val exo = player ?: ExoPlayer.Builder(context).build().also {
            configure(it)
            player = it
        }
        exo.setMediaItem(MediaItem.fromUri(Uri.fromFile(file)))
        setup(exo)
        exo.prepare()
        exo.play()
    }

    /** Stops playback; harmless when nothing plays. */
    fun stop() = onMain { player?.stop() }

    /** Releases the player; the next [play] makes a new one. */
    fun release() = onMain {
        player?.release()
        player = null
    }

    /** The file playing or last played; main thread only (diagnostics and tests). */
    val currentFile: File? get() = player?.currentMediaItem?.localConfiguration?.uri?.path?.let(::File)

    private fun onMain(block: () -> Unit) {
        if (Looper.myLooper() == Looper.getMainLooper()) block() else main.post(block)
    }
}
