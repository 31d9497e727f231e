package org.hapticon.companion.plot

import org.hapticon.companion.cli
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import org.hapticon.testing.TestIcons
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import javax.imageio.ImageIO

class IconPlotTest {
    @get:Rule
    val temp = TemporaryFolder()

    private fun plot(vararg args: String): java.awt.image.BufferedImage {
        val out = File(temp.root, "plot.png")
        val result = cli("plot", *args, "--out", out.path)
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals("wrote $out: 1200×600 PNG\n", result.stdout)
        return ImageIO.read(out)
    }

    @Test
    fun plot_knock_isA1200x600PngOnWhite() {
        val image = plot("knock")
        assertEquals(1200, image.width)
        assertEquals(600, image.height)
        assertTrue(Pixels.isWhite(image.getRGB(3, 3)))
        assertTrue(Pixels.isWhite(image.getRGB(1196, 596)))
    }

    @Test
    fun plot_knock_drawsTheEnvelopeAndItsMirrorAtTheSustainLevel() {
        val image = plot("knock", "--model", "paper")
        val area = IconPlot.area(HapticIcon.KNOCK.duration)
        val x = area.x(0.010) // inside the first pulse's 5..15 ms sustain at 0.5
        assertTrue(Pixels.anyNear(image, x, area.y(0.5), PlotStyle.ENVELOPE))
        assertTrue(Pixels.anyNear(image, x, area.y(-0.5), PlotStyle.ENVELOPE))
        assertFalse(Pixels.anyNear(image, x, area.y(0.8), PlotStyle.ENVELOPE, radius = 4))
    }

    @Test
    fun plot_knock_isEmptyBetweenPulses() {
        val image = plot("knock")
        val area = IconPlot.area(HapticIcon.KNOCK.duration)
        val x = area.x(0.15)
        assertEquals(0, Pixels.countInColumn(image, x, area.y(1.0), area.y(0.05), PlotStyle.ENVELOPE))
        assertEquals(0, Pixels.countInColumn(image, x, area.y(1.0), area.y(0.05), PlotStyle.WAVEFORM))
    }

    @Test
    fun plot_stroke_showsTheCarrierAsABandWithinTheEnvelope() {
        val image = plot("stroke", "--model", "paper")
        val area = IconPlot.area(HapticIcon.STROKE.duration)
        val x = area.x(1.5) // sustain at 0.3; one column spans 10 ms, 3.5 carrier cycles
        val bandRows = Pixels.countInColumn(image, x, area.y(0.25), area.y(-0.25), PlotStyle.WAVEFORM)
        val expectedRows = (area.y(-0.25) - area.y(0.25)).toInt()
        assertTrue("band covers $bandRows of $expectedRows rows", bandRows >= expectedRows - 4)
        assertEquals(0, Pixels.countInColumn(image, x, area.y(1.0), area.y(0.4), PlotStyle.WAVEFORM))
    }

    @Test
    fun plot_processingModel_peaksAtOneWherePaperHoldsTheLevel() {
        val processing = plot("hug") // processing is the default
        val paper = plot("hug", "--model", "paper")
        val area = IconPlot.area(HapticIcon.HUG.duration)
        val x = area.x(1.5) // end of hug's attack: processing 1.0, paper 0.5
        assertTrue(Pixels.anyNear(processing, x, area.y(1.0), PlotStyle.ENVELOPE))
        assertFalse(Pixels.anyNear(paper, x, area.y(1.0), PlotStyle.ENVELOPE, radius = 4))
        assertTrue(Pixels.anyNear(paper, x, area.y(0.5), PlotStyle.ENVELOPE))
    }

    @Test
    fun plot_zeroLengthIcon_stillDrawsAxes() {
        val file = temp.newFile("zero.json").also { it.writeText(IconJson.encode(TestIcons.ZERO_LENGTH)) }
        val image = plot(file.path)
        val area = IconPlot.area(0.0)
        // The frame's left edge is drawn in the axis colour.
        assertTrue(Pixels.anyNear(image, area.left.toDouble(), area.y(0.5), PlotStyle.AXIS, radius = 1))
    }

    @Test
    fun plot_noteAboveNyquistAtChosenRate_exitsTwo() {
        val file = temp.newFile("high.json").also { it.writeText(IconJson.encode(TestIcons.NOTE_127)) }
        val out = File(temp.root, "high.png")
        val result = cli("plot", file.path, "--rate", "22050", "--out", out.path)
        assertEquals(2, result.exitCode)
        assertTrue(result.stderr, result.stderr.startsWith("hapticon: cannot render note-127 at 22050 Hz: note: "))
        assertFalse(out.exists())
    }

    @Test
    fun renderColumns_hug_peakAndRmsMatchTheAnalyticEnvelope() {
        val area = IconPlot.area(HapticIcon.HUG.duration)
        val paper = RenderColumns.scan(IconRenderer(HapticIcon.HUG, 44_100, EnvelopeModel.PAPER), area)
        val processing = RenderColumns.scan(IconRenderer(HapticIcon.HUG, 44_100, EnvelopeModel.PROCESSING), area)
        // ∫e² over one envelope: paper L²(A/3 + S + R/3); processing A/3 + S(1 + L + L²)/3 + L²R/3.
        assertEquals(0.5, paper.peak, 1e-12)
        assertEquals(Math.sqrt(0.25 * (0.5 + 1.0 + 0.5 / 3) / 3.0), paper.rms, 1e-4)
        assertEquals(1.0, processing.peak, 1e-4)
        assertEquals(Math.sqrt((0.5 + 1.75 / 3 + 0.25 * 0.5 / 3) / 3.0), processing.rms, 1e-4)
    }

    @Test
    fun renderColumns_everyColumnOfALongIconHasSamples() {
        val area = IconPlot.area(TestIcons.LONGEST.duration)
        val columns = RenderColumns.scan(IconRenderer(TestIcons.LONGEST, 8_000, EnvelopeModel.PAPER), area)
        for (c in 0 until area.width) assertTrue("column $c", columns.waveform.hasValues(c))
        // 64 overlapping repetitions of level 0.7: the envelope never exceeds it.
        assertEquals(0.7, columns.peak, 1e-12)
    }
}
