package org.hapticon.companion.plot

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import java.awt.Rectangle
import java.awt.image.BufferedImage
import java.util.Locale
import kotlin.math.max

/**
 * The envelope-model comparison (`envelope-models.png`): one panel per icon with the paper and Processing
 * envelopes as rendered at a sample rate, each labelled with its peak and RMS over the icon's duration.
 */
object ModelComparisonPlot {
    const val WIDTH: Int = 1200
    const val HEADER_HEIGHT: Int = 64
    const val PANEL_HEIGHT: Int = 290

    private const val MIN_SECONDS = 0.001

    /** Image height for [panels] panels. */
    fun height(panels: Int): Int = HEADER_HEIGHT + panels * PANEL_HEIGHT

    /** Where panel [index]'s data goes for an icon lasting [seconds]. */
    fun area(index: Int, seconds: Double): PlotArea {
        val top = HEADER_HEIGHT + index * PANEL_HEIGHT + 54
        return PlotArea(left = 84, top = top, width = WIDTH - 84 - 32, height = PANEL_HEIGHT - 54 - 62, seconds = max(seconds, MIN_SECONDS), minValue = 0.0, maxValue = 1.08)
    }

    /** Draws one panel per icon in [icons], envelopes rendered at [sampleRate]. */
    fun draw(icons: List<HapticIcon>, sampleRate: Int): BufferedImage {
        require(icons.isNotEmpty()) { "nothing to compare" }
        val (image, g) = PlotStyle.canvas(WIDTH, height(icons.size))
        try {
            Axes.title(
                g, 84, 30, "Envelope models at $sampleRate Hz: paper vs Processing",
                "paper: 0→L over A, hold L for S, L→0 over R  ·  Processing Sound Env.play: 0→1 over A, 1→L over S, L→0 over R",
            )
            for ((index, icon) in icons.withIndex()) drawPanel(g, index, icon, sampleRate)
        } finally {
            g.dispose()
        }
        return image
    }

    private fun drawPanel(g: java.awt.Graphics2D, index: Int, icon: HapticIcon, sampleRate: Int) {
        val area = area(index, icon.duration)
        val paper = RenderColumns.scan(IconRenderer(icon, sampleRate, EnvelopeModel.PAPER), area)
        val processing = RenderColumns.scan(IconRenderer(icon, sampleRate, EnvelopeModel.PROCESSING), area)
        Axes.draw(g, area, Ticks.between(0.0, 1.0, maxTicks = 5), "envelope")
        g.clip = Rectangle(area.left, area.top - 2, area.width + 1, area.height + 3)
        // Processing first and thicker, so that where the two coincide (every release) both stay visible.
        g.stroke = PlotStyle.THICK_CURVE
        g.color = PlotStyle.PROCESSING
        processing.envelope.draw(g, area)
        g.stroke = PlotStyle.CURVE
        g.color = PlotStyle.PAPER
        paper.envelope.draw(g, area)
        g.clip = null
        Axes.title(g, area.left, area.top - 28, icon.name, null)
        g.font = PlotStyle.SUBTITLE_FONT
        g.color = PlotStyle.MUTED_TEXT
        g.drawString(IconText.parameters(icon), area.left, area.top - 9)
        Axes.legend(
            g, area.right, area.top - 30,
            listOf(
                LegendEntry("paper: peak ${fixed(paper.peak)}, RMS ${fixed(paper.rms)}", PlotStyle.PAPER),
                LegendEntry("processing: peak ${fixed(processing.peak)}, RMS ${fixed(processing.rms)}", PlotStyle.PROCESSING),
            ),
        )
    }

    private fun fixed(value: Double): String = String.format(Locale.ROOT, "%.3f", value)
}
