package org.hapticon.companion.study

import org.hapticon.companion.cli
import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.study.compliance.ComplianceAnswersCsv
import org.hapticon.study.compliance.ComplianceSimulation
import org.hapticon.study.compliance.ComplianceStudy
import org.hapticon.study.compliance.DrawingPoint
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import javax.imageio.ImageIO

class ComplianceAnalysisCommandTest {
    @get:Rule
    val folder = TemporaryFolder()

    private fun rect(x0: Double, y0: Double, x1: Double, y1: Double) = listOf(DrawingPoint(x0, y0), DrawingPoint(x1, y0), DrawingPoint(x1, y1), DrawingPoint(x0, y1))

    /** Each shape's outline as a careful participant would draw it over the active electrodes' cells. */
    private val drawn = mapOf(
        ElectrodeMask.LARGE_SQUARE to rect(0.1, 0.1, 0.9, 0.9),
        ElectrodeMask.SMALL_SQUARE to rect(0.1, 0.1, 0.63, 0.63),
        ElectrodeMask.HORIZONTAL_LINE to rect(0.1, 0.1, 0.9, 0.63),
        ElectrodeMask.VERTICAL_LINE to rect(0.1, 0.1, 0.63, 0.9),
        ElectrodeMask.TRIANGLE to listOf(0.1 to 0.1, 0.37 to 0.1, 0.37 to 0.37, 0.63 to 0.37, 0.63 to 0.63, 0.9 to 0.63, 0.9 to 0.9, 0.1 to 0.9).map { DrawingPoint(it.first, it.second) },
    )

    /** Four people's answer files: Task 1 from the simulation, Task 2 drawn as [drawn], one trial felt less compliant. */
    private fun answerFiles(): List<File> {
        val ratings = ComplianceSimulation.answers(participants = 4, seed = 5)
        return ratings.groupBy { it.participant }.entries.mapIndexed { p, (participant, own) ->
            val task1 = ComplianceStudy.PROTOCOL.trials(p)
            val rows = task1.map { trial -> ComplianceAnswersCsv.ratingRow(ComplianceStudy.PROTOCOL, participant, trial, own.first { it.condition == trial.condition && it.repetition == trial.repetition }.value) } +
                ComplianceStudy.SHAPES_PROTOCOL.trials(p).map { trial ->
                    val less = p == 0 && trial.index == 0
                    ComplianceAnswersCsv.drawingRow(ComplianceStudy.SHAPES_PROTOCOL, participant, trial, !less, if (less) emptyList() else listOf(drawn.getValue(trial.condition.mask)))
                }
            folder.newFile("$participant.csv").apply { writeText(ComplianceAnswersCsv.HEADER + "\n" + rows.joinToString("\n") + "\n") }
        }
    }

    @Test
    fun analysis_ofTheAppsFiles_printsBothTasks_andWritesFigure5() {
        val files = answerFiles()
        val out = File(folder.root, "figures")
        val result = cli("compliance-analysis", *files.map { it.path }.toTypedArray(), "--out", out.path)
        assertEquals(result.toString(), 0, result.exitCode)
        val text = result.stdout
        assertTrue(text, text.startsWith("compliance-analysis: 4 file(s), 144 ratings, 60 drawings\n"))
        assertTrue(text, Regex("""grains:electrode\s+F\(9, 173\)""").containsMatchIn(text))
        assertTrue(text, text.contains("task 2: 4 participants, 60 drawings, 1 felt less compliant than the desk and left out"))
        // Every shape's heatmap shows the cells of its active electrodes.
        for ((mask, _) in drawn) {
            val name = mask.name.lowercase().replace('_', '-')
            assertTrue(text, Regex("""$name\s+\d+ drawings\s+felt ${Regex.escape(mask.pattern.toString())}\s+active ${Regex.escape(mask.pattern.toString())}""").containsMatchIn(text))
            val image = ImageIO.read(File(out, "heatmap-$name.png"))
            assertEquals(20 + 180 + 20 + 340 + 20, image.width)
        }
    }

    @Test
    fun analysis_badFile_isOneLine_exitTwo() {
        val bad = folder.newFile("bad.csv").apply { writeText("participant,trial\n") }
        val result = cli("compliance-analysis", bad.path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: ${bad.path}:1: not a compliance answers file (the header must be ${ComplianceAnswersCsv.HEADER})"), result.stderrLines)
        val badRow = folder.newFile("row.csv").apply { writeText(ComplianceAnswersCsv.HEADER + "\nshaping-compliance,P000-A,1,1,g9-large-square,9,large-square,XXX/XXX/XXX,soft,,\n") }
        assertEquals(listOf("hapticon: ${badRow.path}:2: rating 'soft' is not a number"), cli("compliance-analysis", badRow.path).stderrLines)
        assertEquals(listOf("hapticon: compliance-analysis needs at least one answers file"), cli("compliance-analysis").stderrLines)
    }
}
