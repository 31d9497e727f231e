package org.hapticon.companion.study

import org.hapticon.companion.cli
import org.hapticon.companion.plot.Pixels
import org.hapticon.companion.plot.PlotStyle
import org.hapticon.testing.StudyResults
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import javax.imageio.ImageIO

class AnalyzeCommandTest {
    @get:Rule val temp = TemporaryFolder()

    private fun example(): File = temp.newFile("results.csv").apply { writeText(StudyResults.exampleCsv()) }

    @Test fun writesTablesAndPlotsWithHolm() {
        val out = File(temp.root, "analysis")
        val result = cli("analyze", example().path, "--out", out.path, "--holm")
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals(
            listOf("descriptives.csv", "descriptives.md", "pairwise.csv", "pairwise.md", "boxplot-calm.png", "boxplot-urgent.png").sorted(),
            out.list()!!.sorted(),
        )
        // Reference values: scipy.stats.ttest_rel / wilcoxon(method="approx", correction=True) on the example.
        assertEquals(
            """
            task,icon_a,icon_b,n,t,df,p,p_holm,d,V,p_wilcoxon,p_wilcoxon_holm,dropped
            calm,stroke,hug,5,-1.63299,4,0.177808,0.177808,-0.730297,0,0.345779,0.345779,P06
            calm,stroke,knock,6,3.79628,5,0.0126766,0.0259074,1.54983,15,0.0533369,0.160011,
            calm,hug,knock,5,4.80196,4,0.00863579,0.0259074,2.1475,15,0.0579073,0.160011,P06
            urgent,knock,hit,6,7.74597,5,0.000573245,0.000573245,3.16228,21,0.0310325,0.0310325,
            """.trimIndent() + "\n",
            File(out, "pairwise.csv").readText(),
        )
        val descriptives = File(out, "descriptives.csv").readLines()
        assertEquals("task,icon,n,mean,sd,median,q1,q3,iqr,min,max", descriptives[0])
        assertEquals("calm,stroke,6,4.16667,0.752773,4,4,4.75,0.75,3,5", descriptives[1])
        assertEquals("calm,hug,5,4.6,0.547723,5,4,5,1,4,5", descriptives[2])
        assertEquals(6, descriptives.size)
        assertTrue(result.stdout, result.stdout.contains("| calm | stroke | knock | 6 | 3.796 | 5 | 0.01268 | 0.02591 | 1.55 |"))
        assertTrue(result.stdout, result.stdout.contains("calm stroke vs hug: dropped P06 (rated only one of the pair)"))
        assertTrue(result.stderr, result.stderr.contains("boxplot-urgent.png: 480×440 PNG"))
    }

    @Test fun boxPlotShowsMedianBoxAndMean() {
        val out = File(temp.root, "a")
        assertEquals(0, cli("analyze", example().path, "--out", out.path).exitCode)
        val image = ImageIO.read(File(out, "boxplot-calm.png"))
        assertEquals(480, image.width)
        assertEquals(StudyBoxPlot.HEIGHT, image.height)
        val boxes = StudyResults.EXAMPLE_RATINGS.filterKeys { it.first == "calm" }.map { (key, values) ->
            StudyBoxPlot.IconBox.of(key.second, values.filterNotNull().map { it.toDouble() })
        }
        val area = StudyBoxPlot.area(boxes)
        assertEquals(0.5, area.minValue, 0.0)
        assertEquals(5.5, area.maxValue, 0.0)
        // stroke: median 4, q3 4.75, mean 4.1667; knock: median 2, q1 1.25.
        val strokeX = area.x(0.5)
        assertTrue(Pixels.anyNear(image, strokeX - 20, area.y(4.0), StudyBoxPlot.MEDIAN, radius = 1))
        assertTrue(Pixels.anyNear(image, strokeX - 20, area.y(4.4), StudyBoxPlot.BOX_FILL, radius = 0))
        assertTrue(Pixels.anyNear(image, strokeX, area.y(4.0 + 1.0 / 6.0), StudyBoxPlot.MEAN, radius = 1))
        val knockX = area.x(2.5)
        assertTrue(Pixels.anyNear(image, knockX + 20, area.y(2.0), StudyBoxPlot.MEDIAN, radius = 1))
        assertFalse(Pixels.anyNear(image, knockX + 20, area.y(3.0), StudyBoxPlot.MEDIAN, radius = 3))
        // Outside the box, left of the whisker: background.
        assertTrue(Pixels.isWhite(image.getRGB((knockX - 45).toInt(), area.y(1.5).toInt())))
    }

    @Test fun outliersAreDotsBeyondTheWhiskers() {
        val box = StudyBoxPlot.IconBox.of("hit", listOf(3.0, 3.0, 3.0, 3.0, 1.0))
        assertEquals(listOf(1.0), box.outliers)
        assertEquals(3.0, box.lowWhisker, 0.0)
        val image = StudyBoxPlot.draw("t", 5, listOf(box))
        val area = StudyBoxPlot.area(listOf(box))
        assertTrue(Pixels.anyNear(image, area.x(0.5), area.y(1.0), PlotStyle.TEXT, radius = 1))
        assertTrue(Pixels.isWhite(image.getRGB(area.x(0.5).toInt(), area.y(1.5).toInt()))) // no whisker down to it
    }

    @Test fun onlyTheRequestedTestIsComputed() {
        val out = File(temp.root, "w")
        assertEquals(0, cli("analyze", example().path, "--out", out.path, "--test", "wilcoxon").exitCode)
        assertEquals("urgent,knock,hit,6,,,,,,21,0.0310325,,", File(out, "pairwise.csv").readLines()[4])
    }

    @Test fun badInputIsAOneLineUsageError() {
        val bad = temp.newFile("bad.csv").apply { writeText("participant,task,icon,response\nP1,t,a,4\nP1,t,b,oops\n") }
        val result = cli("analyze", bad.path, "--out", File(temp.root, "x").path)
        assertEquals(2, result.exitCode)
        assertEquals(listOf("hapticon: ${bad.path}:3: response 'oops' is not a finite decimal number"), result.stderrLines)
        assertEquals(listOf("hapticon: no such file: nope.csv"), cli("analyze", "nope.csv").stderrLines)
        assertEquals(listOf("hapticon: --test must be t or wilcoxon or both, got 'z'"), cli("analyze", example().path, "--test", "z").stderrLines)
        val empty = temp.newFile("empty.csv").apply { writeText("participant,task,icon,response\n") }
        assertEquals(listOf("hapticon: ${empty.path}: no responses after the header"), cli("analyze", empty.path).stderrLines)
    }
}
