package org.hapticon.companion.study

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.plot.PngExport
import org.hapticon.sensor.electrotactile.ElectrodePattern
import org.hapticon.study.analysis.ArtContrast
import org.hapticon.study.analysis.ArtEffect
import org.hapticon.study.compliance.ComplianceAnalysis
import org.hapticon.study.compliance.ComplianceAnalysisResult
import org.hapticon.study.compliance.ComplianceAnswersCsv
import org.hapticon.study.compliance.ComplianceCondition
import org.hapticon.study.compliance.ComplianceStudy
import org.hapticon.study.compliance.MagnitudeEstimate
import org.hapticon.study.compliance.ShapeDrawing
import org.hapticon.study.compliance.ShapeDrawings
import org.hapticon.study.compliance.ShapeHeatmap
import java.awt.Color
import java.awt.image.BufferedImage
import java.io.File
import java.io.PrintStream
import java.util.Locale

/**
 * `hapticon compliance-analysis ANSWERS.csv... [--out DIR]`: Shaping Compliance's analysis of the app's compliance
 * answer files ([ComplianceAnswersCsv]): Task 1's ratings standardized per participant and repetition, the reference
 * rows added and ART ANOVA with ART-C contrasts ([ComplianceAnalysis]); Task 2's drawings as Figure 5's heatmaps
 * ([ShapeDrawings]), summarised as the 3×3 cells felt, and with `--out` written as one PNG per shape.
 */
fun runComplianceAnalysis(args: List<String>, console: Console) {
    val arguments = Arguments.parse("compliance-analysis", args, valueOptions = setOf("out"))
    val files = arguments.positionals
    if (files.isEmpty()) throw UsageException("compliance-analysis needs at least one answers file")
    val ratings = ArrayList<MagnitudeEstimate>()
    val drawings = ArrayList<ShapeDrawing>()
    for (path in files) {
        val file = File(path)
        if (!file.isFile) throw UsageException("$path: no such file")
        val answers = try {
            ComplianceAnswersCsv.read(file.readText(), path)
        } catch (e: IllegalArgumentException) {
            throw UsageException(e.message ?: "$path: unreadable")
        }
        ratings += answers.ratings
        drawings += answers.drawings
    }
    val out = console.out
    out.println("compliance-analysis: ${files.size} file(s), ${ratings.size} ratings, ${drawings.size} drawings")
    if (ratings.isNotEmpty()) {
        val result = try {
            ComplianceAnalysis.run(ratings)
        } catch (e: IllegalArgumentException) {
            throw UsageException("task 1: ${e.message}")
        }
        printTask1(result, out)
    }
    if (drawings.isNotEmpty()) {
        val heatmaps = ShapeDrawings.heatmaps(drawings)
        printTask2(heatmaps, drawings, out)
        arguments.value("out")?.let { path ->
            val dir = File(path)
            OutputFiles.ensureDirectory(dir)
            for (heatmap in heatmaps) {
                out.println(PngExport.write(ComplianceHeatmapImage.draw(heatmap), File(dir, "heatmap-${ComplianceCondition.shapeName(heatmap.shape)}.png")))
            }
        }
    }
}

/** Task 1's figures as the paper reports them, for `compliance-analysis` and `replicate 003`. */
internal fun printTask1(result: ComplianceAnalysisResult, out: PrintStream) {
    out.println()
    out.println("task 1: ${result.participants} participants; scores / SD per participant and repetition; reference rows at 0 added")
    if (result.leftOut > 0) out.println("  ${result.leftOut} answers to conditions outside the published twelve (0 grains asked, triangle) left out")
    out.println("  median standardized score (Figure 4a):")
    out.println("  " + "grains".padStart(6) + ComplianceStudy.SHAPES.joinToString("") { ComplianceCondition.shapeName(it).padStart(17) })
    for (g in result.cells.map { it.grains }.distinct()) {
        val row = ComplianceStudy.SHAPES.joinToString("") { shape ->
            (result.cells.firstOrNull { it.grains == g && it.shape == shape }?.let { String.format(Locale.ROOT, "%.2f", it.median) } ?: "—").padStart(17)
        }
        out.println("  " + "$g".padStart(6) + row)
    }
    out.println("  ART ANOVA, grains × electrode (Figure 4a):")
    for (e in result.grainsByShape) out.println("    " + effectLine(e))
    out.println("  ART-C, grains:")
    for (c in result.grainContrasts) out.println("    " + contrastLine(c))
    out.println("  ART ANOVA, number of electrodes (Figure 4b): " + effectLine(result.electrodeCount))
    out.println("  ART-C, electrodes:")
    for (c in result.electrodeContrasts) out.println("    " + contrastLine(c))
    out.println("  ART ANOVA, horizontal vs vertical line (Figure 4c): " + effectLine(result.orientation))
}

private fun printTask2(heatmaps: List<ShapeHeatmap>, drawings: List<ShapeDrawing>, out: PrintStream) {
    out.println()
    val removed = drawings.count { !it.moreCompliant }
    out.println("task 2: ${drawings.map { it.participant }.distinct().size} participants, ${drawings.size} drawings, $removed felt less compliant than the desk and left out")
    out.println("  heatmaps (Figure 5: 340×340 per participant's bounding box, 256 levels, shown from 128); 3×3 cells mostly shown vs active electrodes:")
    for (h in heatmaps) {
        out.println(String.format(Locale.ROOT, "    %-16s %3d drawings  felt %-11s  active %s", ComplianceCondition.shapeName(h.shape), h.drawings, h.feltCells()?.toString() ?: "none", h.shape.pattern))
    }
}

/** `grains:electrode  F(9, 723) = 12.34  p = 1.2e-05`. */
internal fun effectLine(e: ArtEffect): String =
    String.format(Locale.ROOT, "%-18s F(%d, %d) = %8.2f  %s", e.effect, e.dfEffect, e.dfError, e.f, pText(e.p))

/** `9 − 19  t(723) = -4.56  p = 1.0e-04 (Tukey)`. */
internal fun contrastLine(c: ArtContrast): String =
    String.format(Locale.ROOT, "%-22s t(%d) = %7.2f  %s (Tukey)", "${c.first} − ${c.second}", c.df, c.t, pText(c.p))

private fun pText(p: Double): String = when {
    p < 1e-16 -> "p < 1e-16"
    p < 0.001 -> String.format(Locale.ROOT, "p = %.1e", p)
    else -> String.format(Locale.ROOT, "p = %.3f", p)
}

/** Figure 5's panel for one shape: the 3×3 array (orange active, grey inactive) beside the heatmap (blue to red, levels ≥ 128). */
internal object ComplianceHeatmapImage {
    private const val CELL = 60
    private const val GAP = 20

    fun draw(heatmap: ShapeHeatmap): BufferedImage {
        val size = ShapeDrawings.SIZE
        val width = GAP + 3 * CELL + GAP + size + GAP
        val height = GAP + size + GAP
        val image = BufferedImage(width, height, BufferedImage.TYPE_INT_RGB)
        val g = image.createGraphics()
        g.color = Color.WHITE
        g.fillRect(0, 0, width, height)
        val top = GAP + (size - 3 * CELL) / 2
        for (e in 0 until ElectrodePattern.SIZE * ElectrodePattern.SIZE) {
            g.color = if (heatmap.shape.pattern.isOn(e / 3, e % 3)) Color(0xF2, 0x8C, 0x28) else Color(0xB0, 0xB0, 0xB0)
            g.fillOval(GAP + (e % 3) * CELL + 8, top + (e / 3) * CELL + 8, CELL - 16, CELL - 16)
        }
        val left = GAP + 3 * CELL + GAP
        g.color = Color(0x20, 0x20, 0x20)
        g.drawRect(left - 1, GAP - 1, size + 1, size + 1)
        for (y in 0 until size) for (x in 0 until size) {
            val level = heatmap.level(x, y)
            if (level >= ShapeDrawings.THRESHOLD) image.setRGB(left + x, GAP + y, jet(level / 255.0))
        }
        g.dispose()
        return image
    }

    /** Blue (low) through green and yellow to red (high), as the paper's "higher is close to red, lower is to blue". */
    private fun jet(v: Double): Int {
        fun channel(x: Double) = (255 * x.coerceIn(0.0, 1.0)).toInt()
        val r = channel(1.5 - kotlin.math.abs(4 * v - 3))
        val gr = channel(1.5 - kotlin.math.abs(4 * v - 2))
        val b = channel(1.5 - kotlin.math.abs(4 * v - 1))
        return (r shl 16) or (gr shl 8) or b
    }
}
