package org.hapticon.companion

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.AudioSettings
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.DEFAULT_SAMPLE_RATE
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.cli.WavExport
import org.hapticon.companion.chat.MessagingDemo
import org.hapticon.companion.gesture.GestureDemo
import org.hapticon.companion.plot.IconPlot
import org.hapticon.companion.plot.ModelComparisonPlot
import org.hapticon.companion.plot.PngExport
import org.hapticon.companion.sensors.SensorDemo
import org.hapticon.companion.study.StudyDemo
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.IconRenderer
import java.io.File
import java.util.Locale

/** `hapticon demo --out DIR [--apk PATH]`. */
fun runDemo(args: List<String>, console: Console) {
    val arguments = Arguments.parse("demo", args, valueOptions = setOf("out", "apk"))
    arguments.requireNoPositionals()
    val dir = File(arguments.required("out"))
    val apk = arguments.value("apk")?.let(::File)
    if (apk != null && !apk.isFile) throw UsageException("--apk: no such file: $apk")
    writeDemo(dir, apk) { console.out.println(it) }
}

/**
 * Writes the demo into [dir]: each preset as `<name>.wav` (float32, 44.1 kHz, processing model, the default) and
 * `<name>.png`, then `envelope-models.png`, then the [SensorDemo] files, then the [MessagingDemo] exchange
 * and `received-knock.wav`, then the [StudyDemo] (`study/`) and the [GestureDemo] (`gesture/`); reports each
 * file and the [apk]
 * (with its size) through [report].
 * One step per line so that later demo parts (broker, chat) slot in as further steps.
 */
fun writeDemo(dir: File, apk: File?, report: (String) -> Unit) {
    OutputFiles.ensureDirectory(dir)
    for (icon in HapticIcon.PRESETS) {
        report(WavExport.write(icon, AudioSettings(), File(dir, "${icon.name}.wav")))
        val renderer = IconRenderer(icon, DEFAULT_SAMPLE_RATE)
        report(PngExport.write(IconPlot.draw(renderer), File(dir, "${icon.name}.png")))
    }
    val comparison = ModelComparisonPlot.draw(HapticIcon.PRESETS, DEFAULT_SAMPLE_RATE)
    report(PngExport.write(comparison, File(dir, "envelope-models.png")))
    SensorDemo.write(dir, report)
    MessagingDemo.write(dir, report)
    StudyDemo.write(dir, report)
    GestureDemo.write(dir, report)
    if (apk != null) report(String.format(Locale.ROOT, "APK: %s (%d bytes, %.1f MB)", apk, apk.length(), apk.length() / 1e6))
}
