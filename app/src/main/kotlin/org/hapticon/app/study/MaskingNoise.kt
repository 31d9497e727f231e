package org.hapticon.app.study

import android.content.Context
import androidx.annotation.OptIn
import androidx.media3.common.AudioAttributes
import androidx.media3.common.C
import androidx.media3.common.Player
import androidx.media3.common.util.UnstableApi
import androidx.media3.exoplayer.ExoPlayer
import org.hapticon.app.playback.MainThreadFilePlayer
import org.hapticon.app.playback.writeWholeFile
import java.io.File
import java.io.IOException
import kotlin.math.pow
import org.hapticon.core.io.WavWriter

/**
 * The looping noise files, rendered once per color into [directory]: 10 s of PCM16 at 48 kHz with an RMS of
 * [RENDER_LEVEL_DBFS]. The playback level is the player's volume below that, so the file's level is the hard cap.
 */
class NoiseFiles(private val directory: File, private val seed: Long = SEED) {
    /** The WAV file of [color], rendered now if it is not there. Throws [IOException] when the directory is not writable. */
    @Throws(IOException::class)
    fun fileFor(color: NoiseColor): File {
        require(color != NoiseColor.OFF) { "no file for OFF" }
        val file = File(directory, "${color.name.lowercase()}-$seed-${SAMPLE_RATE}.wav")
        if (file.isFile) return file
        val samples = NoiseGenerator.samples(color, SAMPLE_RATE, SAMPLE_RATE * SECONDS, seed, RENDER_LEVEL_DBFS)
        writeWholeFile(file) { WavWriter.write(NoiseGenerator.stream(samples, SAMPLE_RATE), it) }
        return file
    }

    companion object {
        /** The native rate of phone audio HALs. */
        const val SAMPLE_RATE: Int = 48_000

        /** Length of the loop. Long enough that nobody hears it repeat. */
        const val SECONDS: Int = 10

        /** The seed of every masking file, so that all participants hear the same noise. */
        const val SEED: Long = 20_240_501L

        /** RMS level of the rendered file, and so the loudest the noise can play (player volume 1). */
        const val RENDER_LEVEL_DBFS: Double = -12.0

        /** The cap of the level slider: the rendered level. */
        const val MAX_LEVEL_DBFS: Double = RENDER_LEVEL_DBFS

        /** The bottom of the level slider. */
        const val MIN_LEVEL_DBFS: Double = -60.0

        /** The level a new protocol starts with. */
        const val DEFAULT_LEVEL_DBFS: Double = -30.0

        /** The player volume (linear gain, 0..1) that plays a file rendered at [RENDER_LEVEL_DBFS] at [levelDbfs]. */
        fun volumeFor(levelDbfs: Double): Float {
            val capped = if (levelDbfs.isNaN()) MIN_LEVEL_DBFS else levelDbfs.coerceIn(MIN_LEVEL_DBFS, MAX_LEVEL_DBFS)
            return 10.0.pow((capped - RENDER_LEVEL_DBFS) / 20).toFloat()
        }
    }
}

/** Plays the masking noise of a session during its tasks. */
interface MaskingNoisePlayer {
    /** Starts [setting]'s noise looping (or stops it for [NoiseColor.OFF]); a second start replaces the first. */
    fun start(setting: MaskingSetting)

    /** Stops the noise. Safe when nothing plays. */
    fun stop()
}

/**
 * [MaskingNoisePlayer] through Media3's ExoPlayer: the noise file of [files] with REPEAT_MODE_ONE at the setting's
 * volume. ExoPlayer is made lazily and touched only on the main thread, as it requires; rendering a file the first
 * time (about 0.2 s) happens on the caller's thread.
 */
@OptIn(UnstableApi::class)
class Media3MaskingNoisePlayer(context: Context, private val files: NoiseFiles) : MaskingNoisePlayer {
    private val output = MainThreadFilePlayer(context) {
        // Media usage, no audio focus: the noise must not duck or pause for the icon playback.
        it.setAudioAttributes(AudioAttributes.Builder().setUsage(C.USAGE_MEDIA).setContentType(C.AUDIO_CONTENT_TYPE_MUSIC).build(), false)
    }
    private val player: ExoPlayer? get() = output.player

    override fun start(setting: MaskingSetting) {
        if (!setting.isOn) return stop()
        val file = try {
            files.fileFor(setting.color)
        } catch (e: IOException) {
            android.util.Log.w(TAG, "no masking noise: ${e.message}")
            return
        }
        output.play(file) { exo ->
            exo.repeatMode = Player.REPEAT_MODE_ONE
            exo.volume = NoiseFiles.volumeFor(setting.levelDbfs)
        }
    }

    override fun stop() = output.stop()

    /** The file playing or last played; main thread only (diagnostics and tests). */
    val currentFile: File? get() = output.currentFile

    /** The repeat mode; main thread only. */
    val repeatMode: Int get() = player?.repeatMode ?: Player.REPEAT_MODE_OFF

    /** The volume; main thread only. */
    val volume: Float get() = player?.volume ?: 0f

    /** Whether the player is asked to play (it may still be preparing); main thread only. */
    val isPlayRequested: Boolean get() = player?.let { it.playWhenReady && it.playbackState != Player.STATE_IDLE } ?: false

    /** Releases the player. */
    fun release() = output.release()

    private companion object {
        const val TAG = "MaskingNoise"
    }
}
