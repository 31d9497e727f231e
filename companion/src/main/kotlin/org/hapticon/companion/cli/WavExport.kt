package org.hapticon.companion.cli

import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException
import org.hapticon.core.io.WavEncoding
import org.hapticon.core.io.WavWriter
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import org.hapticon.core.render.PcmRenderer
import org.hapticon.core.render.RenderMode
import java.io.File
import java.util.Locale

/** How to render an icon to audio. */
data class AudioSettings(
    val sampleRate: Int = DEFAULT_SAMPLE_RATE,
    val encoding: WavEncoding = WavEncoding.FLOAT32,
    val model: EnvelopeModel = EnvelopeModel.DEFAULT,
    val mode: RenderMode = RenderMode.EXACT,
)

/** Streams icons into WAV files; the whole signal is never in memory. */
object WavExport {
    /**
     * Renders [icon] with [settings] into [file] and returns a one-line summary of what was written.
     * Throws [UsageException] when the icon cannot be rendered at the rate or the file cannot be written;
     * the renderer is built first, so an invalid request leaves no file behind.
     */
    fun write(icon: HapticIcon, settings: AudioSettings, file: File): String {
        val rate = settings.sampleRate
        val samples = when (settings.encoding) {
            WavEncoding.FLOAT32 -> {
                val renderer = renderable(icon, rate) { IconRenderer(icon, rate, settings.model, settings.mode) }
                OutputFiles.write(file) { WavWriter.write(renderer.stream(), it, WavEncoding.FLOAT32) }
                renderer.sampleCount
            }
            // PcmRenderer converts from doubles, so each sample is rounded once (not double → float → short).
            WavEncoding.PCM16 -> {
                val renderer = renderable(icon, rate) { PcmRenderer(icon, rate, settings.model, settings.mode) }
                OutputFiles.write(file) { WavWriter.write(renderer.stream(), it) }
                renderer.sampleCount
            }
        }
        return String.format(
            Locale.ROOT,
            "wrote %s: %s, %d samples, %.3f s at %d Hz, %s, %s model, %s mode",
            file, icon.name, samples, samples.toDouble() / rate, rate,
            settings.encoding.cliName(), settings.model.cliName(), settings.mode.name.lowercase(),
        )
    }
}

/**
 * Runs [build] (a renderer constructor), reporting an icon that cannot be rendered at [sampleRate]
 * (rate out of range, carrier at or above Nyquist) as a [UsageException].
 */
inline fun <T> renderable(icon: HapticIcon, sampleRate: Int, build: () -> T): T = try {
    build()
} catch (e: IconValidationException) {
    throw UsageException("cannot render ${icon.name} at $sampleRate Hz: ${e.message}")
}
