package org.hapticon.companion.plot

import org.hapticon.companion.cli.cliName
import org.hapticon.core.render.IconRenderer
import java.awt.image.BufferedImage
import kotlin.math.max

/**
 * The picture `hapticon plot` draws: the envelope (and its mirror) over the carrier waveform, with a time
 * axis in seconds, an amplitude axis, and a title listing the icon's parameters. Long icons show the
 * waveform as a min/max band per pixel column, computed by streaming the render once.
 */
object IconPlot {
    const val WIDTH: Int = 1200
    const val HEIGHT: Int = 600

    /** Time span drawn for an icon of zero duration, which still gets axes. */
    private const val MIN_SECONDS = 0.001

    /** Where the data goes for an icon lasting [seconds]. */
    fun area(seconds: Double): PlotArea =
        PlotArea(left = 84, top = 88, width = WIDTH - 84 - 32, height = HEIGHT - 88 - 66, seconds = max(seconds, MIN_SECONDS), minValue = -1.1, maxValue = 1.1)

    /** Draws [renderer]'s icon as rendered (same rate and envelope model). */
    fun draw(renderer: IconRenderer): BufferedImage {
        val icon = renderer.icon
        val area = area(icon.duration)
        val columns = RenderColumns.scan(renderer, area)
        val (image, g) = PlotStyle.canvas(WIDTH, HEIGHT)
        try {
            Axes.draw(g, area, Ticks.between(-1.0, 1.0, maxTicks = 5), "amplitude")
            drawEnvelopeOverWaveform(g, area, columns.waveform, columns.envelope)
            val model = renderer.model.cliName()
            Axes.title(g, area.left, 32, "${icon.name} · $model envelope model · ${renderer.sampleRate} Hz", IconText.parameters(icon))
            Axes.legend(
                g, area.right, 28,
                listOf(
                    LegendEntry("envelope (±)", PlotStyle.ENVELOPE),
                    LegendEntry("envelope × carrier", PlotStyle.WAVEFORM, band = true),
                ),
            )
        } finally {
            g.dispose()
        }
        return image
    }
}

/** The waveform band inside [area] with the envelope and its mirror over it, clipped to the area. */
internal fun drawEnvelopeOverWaveform(g: java.awt.Graphics2D, area: PlotArea, waveform: ColumnExtremes, envelope: ColumnExtremes) {
    g.clip = java.awt.Rectangle(area.left, area.top, area.width + 1, area.height + 1)
    g.stroke = PlotStyle.THIN
    g.color = PlotStyle.WAVEFORM
    waveform.draw(g, area)
    g.stroke = PlotStyle.CURVE
    g.color = PlotStyle.ENVELOPE
    envelope.draw(g, area)
    envelope.draw(g, area, scale = -1.0)
    g.clip = null
}
