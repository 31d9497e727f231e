package org.hapticon.companion.plot

import org.hapticon.companion.cli
import org.hapticon.core.pattern.FrequencyMapping
import org.hapticon.core.pattern.PatternFiles
import org.hapticon.core.pattern.PatternFormat
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import javax.imageio.ImageIO

class PatternPlotTest {
    @get:Rule
    val temp = TemporaryFolder()

    // A .haptic: 0.5 held 0..0.2 s then down to 0 at 0.4 s; the carrier falls from the top of the default range to
    // its bottom; an emphasis (a transient) at 0.2 s.
    private val haptic = """{"version":{"major":1,"minor":0,"patch":0},"signals":{"continuous":{"envelopes":{
        "amplitude":[{"time":0,"amplitude":0.5},{"time":0.2,"amplitude":0.5,"emphasis":{"amplitude":0.9,"frequency":0.25}},{"time":0.4,"amplitude":0}],
        "frequency":[{"time":0,"frequency":1},{"time":0.4,"frequency":0}]}}}}"""

    private fun plot(): Pair<java.awt.image.BufferedImage, File> {
        val file = File(temp.root, "fall.haptic").apply { writeText(haptic) }
        val out = File(temp.root, "fall.png")
        val result = cli("plot", file.path, "--out", out.path)
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals("wrote $out: 1200×820 PNG\n", result.stdout)
        return ImageIO.read(out) to file
    }

    @Test
    fun plot_hapticFile_envelopeAndItsMirrorWhereTheFileHoldsThem() {
        val (image, file) = plot()
        val pattern = PatternFiles.read(file.readBytes(), PatternFormat.HAPTIC, "fall").pattern
        val (top, _) = PatternPlot.areas(pattern)
        assertTrue(Pixels.anyNear(image, top.x(0.1), top.y(0.5), PlotStyle.ENVELOPE))
        assertTrue(Pixels.anyNear(image, top.x(0.1), top.y(-0.5), PlotStyle.ENVELOPE))
        assertTrue(Pixels.anyNear(image, top.x(0.3), top.y(0.25), PlotStyle.ENVELOPE))
        assertFalse(Pixels.anyNear(image, top.x(0.1), top.y(0.8), PlotStyle.ENVELOPE, radius = 4))
    }

    @Test
    fun plot_hapticFile_frequencyFallsAcrossTheRangeAndTheTransientSitsAtItsSharpness() {
        val (image, file) = plot()
        val pattern = PatternFiles.read(file.readBytes(), PatternFormat.HAPTIC, "fall").pattern
        val (_, bottom) = PatternPlot.areas(pattern)
        val mapping = FrequencyMapping.DEFAULT
        assertTrue(Pixels.anyNear(image, bottom.x(0.01), bottom.y(pattern.frequencyAt(0.01)), PatternPlot.FREQUENCY))
        assertTrue(Pixels.anyNear(image, bottom.x(0.39), bottom.y(pattern.frequencyAt(0.39)), PatternPlot.FREQUENCY))
        assertEquals(mapping.maxHz, pattern.frequencyAt(0.0), 1e-9)
        val tap = pattern.transients.single()
        assertTrue(Pixels.anyNear(image, bottom.x(tap.time), bottom.y(mapping.hertzOfSharpness(tap.sharpness)), PatternPlot.TAP))
    }

    @Test
    fun plot_patternAboveNyquist_oneLineUsageError() {
        val file = File(temp.root, "high.json").apply {
            writeText("""{"schema":"hapticon.pattern","version":1,"name":"high","amplitude":[{"time":0,"amplitude":0.5},{"time":0.1,"amplitude":0.5}],"frequency":[{"time":0,"hertz":5000}]}""")
        }
        val result = cli("plot", file.path, "--rate", "8000", "--out", File(temp.root, "x.png").path)
        assertEquals(2, result.exitCode)
        assertEquals("hapticon: cannot render high at 8000 Hz: it reaches 5000.0 Hz, at or above Nyquist\n", result.stderr)
    }
}
