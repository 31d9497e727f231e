package org.hapticon.companion

import org.hapticon.companion.cli.writeWav
import org.hapticon.companion.cli.PatternSource
import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.AudioSettings
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.DEFAULT_SAMPLE_RATE
import org.hapticon.companion.cli.FORMAT_CHOICES
import org.hapticon.companion.cli.IconSource
import org.hapticon.companion.cli.MODEL_CHOICES
import org.hapticon.companion.cli.MODE_CHOICES
import org.hapticon.companion.cli.WavExport
import org.hapticon.core.io.WavEncoding
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.RenderMode
import java.io.File

/** `hapticon render ICON|PATTERN --out FILE.wav [--rate HZ] [--format f32|s16] [--model paper|processing] [--mode exact|fast]`. */
fun runRender(args: List<String>, console: Console) {
    val arguments = Arguments.parse("render", args, valueOptions = setOf("out", "rate", "format", "model", "mode"))
    val spec = arguments.single("an ICON (a preset name, an icon or pattern JSON file, .ahap or .haptic)")
    val settings = AudioSettings(
        sampleRate = arguments.int("rate", DEFAULT_SAMPLE_RATE),
        encoding = arguments.choice("format", FORMAT_CHOICES, WavEncoding.FLOAT32),
        model = arguments.choice("model", MODEL_CHOICES, EnvelopeModel.DEFAULT),
        mode = arguments.choice("mode", MODE_CHOICES, RenderMode.EXACT),
    )
    val file = File(arguments.required("out"))
    val imported = PatternSource.loadIfPattern(spec)
    if (imported != null) {
        // A pattern has no envelope model or render mode: its curves are sampled as they are.
        imported.notes.forEach { console.err.println("hapticon: note: $it") }
        console.out.println(writeWav(imported.pattern, file, settings.sampleRate, settings.encoding))
        return
    }
    val icon = IconSource.load(spec)
    console.out.println(WavExport.write(icon, settings, file))
}
