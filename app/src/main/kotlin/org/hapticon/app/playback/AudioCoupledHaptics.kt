package org.hapticon.app.playback

import android.content.Context
import android.media.AudioManager
import android.media.audiofx.HapticGenerator
import android.os.Build
import android.util.Log
import androidx.annotation.OptIn
import androidx.annotation.RequiresApi
import androidx.media3.common.AudioAttributes
import androidx.media3.common.C
import androidx.media3.common.util.UnstableApi
import androidx.media3.exoplayer.ExoPlayer
import java.io.File
import java.io.IOException
import java.security.MessageDigest
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.hapticon.core.io.WavEncoding
import org.hapticon.core.io.WavReader
import org.hapticon.core.io.WavWriter
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternJson
import org.hapticon.core.pattern.signal
import org.hapticon.core.platform.AndroidVibrationRules
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.stream
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.Fidelity
import org.hapticon.core.render.PcmRenderer

/**
 * Plays audio with the phone's haptic channel unmuted: the audio-coupled haptics path, on the audio clock.
 * The originating study rendered its icons as audio that drove the LRA; this is the same on a phone whose
 * audio HAL can feed the actuator.
 */
interface AudioCoupledOutput {
    /** Whether this phone can play audio-coupled haptics now. */
    val isAvailable: Boolean

    /**
     * Plays [wav] (a PCM16 WAV file) as [usage], replacing whatever this output plays. Android judges the haptic channel
     * by the vibration usage it derives from the stream's audio usage ([AndroidVibrationRules.audioUsageFor]).
     */
    fun play(wav: File, usage: VibrationUsage)

    /** Stops playback. */
    fun stop()
}

/**
 * Renders icons (and patterns, [fileFor]) into PCM16 WAV files in [directory], once per distinct icon, rate and envelope model ([model],
 * the study's `processing` envelope, unless a call names another): the name is a hash of those and the icon's
 * JSON, so a repeat plays from disk at once and a file rendered with another model is never reused. At most [maxFiles] are kept (oldest first out),
 * because an icon is at most 30 s × 48 kHz × 2 bytes ≈ 2.9 MB.
 */
class IconAudioCache(
    private val directory: File,
    val sampleRate: Int = SAMPLE_RATE,
    private val maxFiles: Int = 32,
    val model: EnvelopeModel = EnvelopeModel.DEFAULT,
) {
    /** The WAV file of [icon] with its envelope under [envelopeModel], rendered now if it is not cached. */
    @Throws(IOException::class)
    fun fileFor(icon: HapticIcon, envelopeModel: EnvelopeModel = model): File {
        val file = File(directory, "${keyOf(icon, envelopeModel)}.wav")
        if (file.isFile) {
            file.setLastModified(System.currentTimeMillis())
            return file
        }
        writeWholeFile(file) { WavWriter.write(PcmRenderer(icon, sampleRate, envelopeModel).stream(), it) }
        evict()
        return file
    }

    // Measuring renders the whole icon again in double precision: once per icon, not once per press.
    private val fidelities = object : LinkedHashMap<String, Fidelity>(16, 0.75f, true) {
        override fun removeEldestEntry(eldest: MutableMap.MutableEntry<String, Fidelity>): Boolean = size > maxFiles
    }

    /** How faithfully the PCM16 file of [icon] under [envelopeModel] carries it; measured on first use and remembered. */
    @Synchronized
    fun fidelityOf(icon: HapticIcon, envelopeModel: EnvelopeModel = model): Fidelity =
        fidelities.getOrPut(keyOf(icon, envelopeModel)) { PcmRenderer(icon, sampleRate, envelopeModel).fidelity() }

    /**
     * The WAV file of [pattern]: its signal ([org.hapticon.core.pattern.signal], every frequency key as it is, the
     * transients as bursts) in PCM16 at [sampleRate], rendered now if it is not cached.
     *
     * @throws IllegalArgumentException when the pattern reaches the Nyquist frequency (it cannot be audio here), or
     *   plays longer than the safety cap ([HapticPattern.checkPlayable]).
     */
    @Throws(IOException::class)
    fun fileFor(pattern: HapticPattern): File {
        pattern.checkPlayable()
        require(pattern.frequency.all { it.hertz < sampleRate / 2.0 }) { "${pattern.name} reaches ${sampleRate / 2} Hz, the Nyquist frequency at $sampleRate Hz" }
        val file = File(directory, "${keyOf(pattern)}.wav")
        if (file.isFile) {
            file.setLastModified(System.currentTimeMillis())
            return file
        }
        writeWholeFile(file) { WavWriter.write(pattern.signal().stream(sampleRate), it, WavEncoding.PCM16) }
        evict()
        return file
    }

    /**
     * How faithfully the PCM16 file of [pattern] carries its exact signal: the file read back against
     * `signal().sample(i / sampleRate)`, sample by sample; measured on first use and remembered.
     */
    @Synchronized
    @Throws(IOException::class)
    fun fidelityOf(pattern: HapticPattern): Fidelity = fidelities.getOrPut(keyOf(pattern)) {
        val signal = pattern.signal()
        val block = FloatArray(4096)
        var index = 0L
        var sumOfSquares = 0.0
        var maxError = 0.0
        fileFor(pattern).inputStream().buffered().use { input ->
            val stream = WavReader.stream(input)
            while (true) {
                val n = stream.read(block)
                if (n < 0) break
                for (j in 0 until n) {
                    val error = kotlin.math.abs(block[j] - signal.sample((index + j).toDouble() / sampleRate))
                    sumOfSquares += error * error
                    maxError = maxOf(maxError, error)
                }
                index += n
            }
        }
        Fidelity(if (index == 0L) 0.0 else kotlin.math.sqrt(sumOfSquares / index), maxError, "PCM16 at $sampleRate Hz, $index samples")
    }

    private fun keyOf(pattern: HapticPattern): String {
        val digest = MessageDigest.getInstance("SHA-256").digest("pattern:$sampleRate:${PatternJson.toJsonElement(pattern)}".toByteArray())
        return digest.take(12).joinToString("") { "%02x".format(it) }
    }

    private fun keyOf(icon: HapticIcon, envelopeModel: EnvelopeModel): String {
        val digest = MessageDigest.getInstance("SHA-256").digest("$sampleRate:${envelopeModel.name}:${IconJson.encode(icon)}".toByteArray())
        return digest.take(12).joinToString("") { "%02x".format(it) }
    }

    private fun evict() {
        val files = directory.listFiles { f -> f.name.endsWith(".wav") }?.sortedByDescending { it.lastModified() } ?: return
        for (stale in files.drop(maxFiles)) stale.delete()
    }

    companion object {
        /** The rate phone audio HALs run natively, so nothing is resampled on the way to the actuator. */
        const val SAMPLE_RATE = 48_000
    }
}

/**
 * [AudioCoupledOutput] through Media3's ExoPlayer with haptic channels unmuted, on an audio session that
 * carries the platform's [HapticGenerator] (API 31+), which derives the haptic channel from the audio.
 * Available when the phone supports haptic playback ([AudioManager.isHapticPlaybackSupported]) and has a
 * haptic generator. The player is made lazily and used only on the main thread, as ExoPlayer requires.
 */
@OptIn(UnstableApi::class)
class Media3AudioCoupledOutput(private val context: Context) : AudioCoupledOutput {
    private var generator: Any? = null // HapticGenerator on API 31+; Any keeps the class loadable below.
    private val files = MainThreadFilePlayer(context, ::configure)

    override val isAvailable: Boolean
        get() = Build.VERSION.SDK_INT >= 31 && hapticsAvailable()

    override fun play(wav: File, usage: VibrationUsage) = files.play(wav) { it.setAudioAttributes(audioAttributesFor(usage), false) }

    override fun stop() = files.stop()

    /** The file playing or last played, for the screens' diagnostics and tests; main thread only. */
    val currentFile: File? get() = files.currentFile

    /** The audio attributes of the last play ([audioAttributesFor] its usage), for diagnostics and tests; main thread only. */
    val audioAttributes: AudioAttributes? get() = files.player?.audioAttributes

    /**
     * The audio attributes a play of [usage] uses, haptic channels unmuted: sonification for a press (Android's
     * `VibrationAttributes.Builder(AudioAttributes)` makes the haptic channel TOUCH), an instant-message notification
     * for a received icon (NOTIFICATION: allowed from the background). No audio focus: the icon must not pause music.
     */
    fun audioAttributesFor(usage: VibrationUsage): AudioAttributes = AudioAttributes.Builder()
        .setUsage(AndroidVibrationRules.audioUsageFor(usage).platformValue)
        .setContentType(C.AUDIO_CONTENT_TYPE_SONIFICATION)
        .setHapticChannelsMuted(false)
        .build()

    private fun configure(exo: ExoPlayer) {
        if (Build.VERSION.SDK_INT >= 31) {
            val audio = context.getSystemService(AudioManager::class.java)
            val session = audio.generateAudioSessionId()
            exo.audioSessionId = session
            generator = attachGenerator(session)
        }
    }

    @RequiresApi(31)
    private fun hapticsAvailable(): Boolean =
        runCatching { AudioManager.isHapticPlaybackSupported() && HapticGenerator.isAvailable() }.getOrDefault(false)

    @RequiresApi(31)
    private fun attachGenerator(session: Int): Any? = try {
        HapticGenerator.create(session).apply { enabled = true }
    } catch (e: RuntimeException) {
        // Without the generator the audio still plays; the vibrator path is the caller's fallback next time.
        Log.w(TAG, "no haptic generator on session $session: ${e.message}")
        null
    }

    private companion object {
        const val TAG = "AudioCoupled"
    }
}
