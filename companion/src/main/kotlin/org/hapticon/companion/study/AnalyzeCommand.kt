package org.hapticon.companion.study

import java.io.File
import java.io.IOException
import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.plot.PngExport
import org.hapticon.study.analysis.StudyAnalysis
import org.hapticon.study.analysis.StudyResponse
import org.hapticon.study.export.CsvFormatException

/** Which paired tests `--test` asks for. */
enum class PairedTests(val t: Boolean, val wilcoxon: Boolean) { T(true, false), WILCOXON(false, true), BOTH(true, true) }

/** `--test` values. */
val TEST_CHOICES: Map<String, PairedTests> = linkedMapOf("t" to PairedTests.T, "wilcoxon" to PairedTests.WILCOXON, "both" to PairedTests.BOTH)

/**
 * `hapticon analyze RESULTS.csv [--out DIR] [--holm] [--test t|wilcoxon|both]`: the descriptives and
 * pairwise tables as Markdown to stdout; descriptives.csv/.md, pairwise.csv/.md and one box plot
 * `boxplot-TASK.png` per task into DIR (default ./analysis); one line per written file to stderr.
 */
fun runAnalyze(args: List<String>, console: Console) {
    val arguments = Arguments.parse("analyze", args, valueOptions = setOf("out", "test"), flagOptions = setOf("holm"))
    val path = arguments.single("a results CSV file")
    val tests = arguments.choice("test", TEST_CHOICES, PairedTests.BOTH)
    val holm = arguments.flag("holm")
    val out = File(arguments.value("out") ?: "analysis")
    val responses = readResponses(path)
    if (responses.isEmpty()) throw UsageException("$path: no responses after the header")

    val summaries = StudyAnalysis.describe(responses)
    val comparisons = StudyAnalysis.compare(responses, tTest = tests.t, wilcoxon = tests.wilcoxon, holm = holm)
    console.out.print("## Descriptives\n\n" + AnalysisTables.descriptivesMarkdown(summaries))
    console.out.print("\n## Pairwise comparisons\n\n" + AnalysisTables.pairwiseMarkdown(comparisons))
    val incomplete = comparisons.filter { it.droppedParticipants.isNotEmpty() }
    if (incomplete.isNotEmpty()) console.out.println()
    for (c in incomplete) {
        console.out.println("${c.task} ${c.iconA} vs ${c.iconB}: dropped ${c.droppedParticipants.joinToString(", ")} (rated only one of the pair)")
    }

    OutputFiles.ensureDirectory(out)
    writeText(File(out, "descriptives.csv"), AnalysisTables.descriptivesCsv(summaries), console)
    writeText(File(out, "descriptives.md"), AnalysisTables.descriptivesMarkdown(summaries), console)
    writeText(File(out, "pairwise.csv"), AnalysisTables.pairwiseCsv(comparisons), console)
    writeText(File(out, "pairwise.md"), AnalysisTables.pairwiseMarkdown(comparisons), console)
    for ((task, rows) in responses.groupBy { it.task }) {
        val boxes = rows.groupBy { it.icon }.map { (icon, own) -> StudyBoxPlot.IconBox.of(icon, own.map { it.response }) }
        val image = StudyBoxPlot.draw(task, rows.map { it.participant }.distinct().size, boxes)
        console.err.println(PngExport.write(image, File(out, boxPlotFileName(task))))
    }
}

/** `boxplot-TASK.png`, with characters unsafe in file names replaced by `_`. */
fun boxPlotFileName(task: String): String = "boxplot-" + task.replace(Regex("[^A-Za-z0-9._-]"), "_") + ".png"

private fun readResponses(path: String): List<StudyResponse> {
    val file = File(path)
    if (file.isDirectory) throw UsageException("$file is a directory, not a results CSV")
    if (!file.isFile) throw UsageException("no such file: $file")
    return try {
        file.reader(Charsets.UTF_8).use { ResultsReader.read(it, path) }
    } catch (e: CsvFormatException) {
        throw UsageException(e.message.orEmpty())
    } catch (e: IOException) {
        throw UsageException("cannot read $file: ${e.message}")
    }
}

private fun writeText(file: File, text: String, console: Console) {
    OutputFiles.write(file) { it.write(text.toByteArray(Charsets.UTF_8)) }
    console.err.println("wrote $file")
}
