package org.hapticon.companion.gesture

import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.core.HapticIcon
import org.hapticon.gesture.extraction.NoisyIconRenders
import org.hapticon.gesture.io.RecordingWav
import java.io.ByteArrayOutputStream
import java.io.File
import java.io.PrintStream
import java.util.Random

/**
 * The demo's gesture part: a knock "recorded" as the study did (the knock icon as a vibration-sensor signal at
 * 44.1 kHz, with white noise at [SNR_DB] dB), then fitted back into an icon as `hapticon fit` does.
 */
object GestureDemo {
    /** Signal-to-noise ratio of the synthetic recording. */
    const val SNR_DB = 30.0

    /** Writes `gesture/knock-recording.wav`, `gesture/knock-fit.json` and `gesture/knock-fit.txt` into [dir]. */
    fun write(dir: File, report: (String) -> Unit) {
        val out = File(dir, "gesture")
        OutputFiles.ensureDirectory(out)
        val recording = NoisyIconRenders.render(HapticIcon.KNOCK, SNR_DB, Random(7)).toRecording()
        val wav = File(out, "knock-recording.wav")
        OutputFiles.write(wav) { RecordingWav.write(recording, it) }
        report("wrote $wav: a knock recorded at 44.1 kHz with noise at ${SNR_DB.toInt()} dB SNR")
        val json = File(out, "knock-fit.json")
        val text = ByteArrayOutputStream()
        runFit(listOf("--in", wav.path, "--out", json.path, "--name", "knock-fitted"), Console(PrintStream(text, true, "UTF-8"), System.err))
        val summary = File(out, "knock-fit.txt")
        OutputFiles.write(summary) { it.write(text.toByteArray()) }
        report("wrote $json and $summary: the icon fitted to the recording, and its fit report")
    }
}
