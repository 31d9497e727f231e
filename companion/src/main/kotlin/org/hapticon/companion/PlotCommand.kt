package org.hapticon.companion

import org.hapticon.companion.cli.renderable
import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.DEFAULT_SAMPLE_RATE
import org.hapticon.companion.cli.IconSource
import org.hapticon.companion.cli.MODEL_CHOICES
import org.hapticon.companion.plot.IconPlot
import org.hapticon.companion.plot.PngExport
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import java.io.File

/** `hapticon plot ICON --out FILE.png [--model paper|processing] [--rate HZ]`. */
fun runPlot(args: List<String>, console: Console) {
    val arguments = Arguments.parse("plot", args, valueOptions = setOf("out", "model", "rate"))
    val spec = arguments.single("an ICON (a preset name or an icon JSON file)")
    val model = arguments.choice("model", MODEL_CHOICES, EnvelopeModel.DEFAULT)
    val rate = arguments.int("rate", DEFAULT_SAMPLE_RATE)
    val file = File(arguments.required("out"))
    val icon = IconSource.load(spec)
    val renderer = renderable(icon, rate) { IconRenderer(icon, rate, model) }
    console.out.println(PngExport.write(IconPlot.draw(renderer), file))
}
