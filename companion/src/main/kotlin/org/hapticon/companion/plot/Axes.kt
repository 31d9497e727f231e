package org.hapticon.companion.plot

import java.awt.Color
import java.awt.Graphics2D
import java.awt.geom.Line2D
import kotlin.math.roundToInt

/** One legend entry: a short line (or a filled swatch when [band]) in [color], then [label]. */
class LegendEntry(val label: String, val color: Color, val band: Boolean = false)

/** Drawing of the parts around the data: grid, frame, ticks, axis labels, titles and legends. */
object Axes {
    /**
     * Draws the grid, frame and tick labels of [area]: time ticks in seconds along the bottom,
     * [valueTicks] on the left, and the axis labels. The zero value line is drawn darker.
     */
    fun draw(g: Graphics2D, area: PlotArea, valueTicks: Ticks, valueLabel: String) {
        val timeTicks = Ticks.between(0.0, area.seconds, maxTicks = (area.width / 90).coerceIn(2, 16))
        val line = Line2D.Double()
        g.stroke = PlotStyle.THIN
        g.color = PlotStyle.GRID
        for (t in timeTicks.values) g.draw(line.also { it.setLine(area.x(t), area.top.toDouble(), area.x(t), area.bottom.toDouble()) })
        valueAxis(g, area, valueTicks, valueLabel)

        g.font = PlotStyle.TICK_FONT
        val metrics = g.fontMetrics
        for (t in timeTicks.values) {
            val x = area.x(t)
            g.color = PlotStyle.AXIS
            g.draw(line.also { it.setLine(x, area.bottom.toDouble(), x, area.bottom + 5.0) })
            val label = timeTicks.label(t)
            g.color = PlotStyle.MUTED_TEXT
            g.drawString(label, (x - metrics.stringWidth(label) / 2.0).roundToInt(), area.bottom + 7 + metrics.ascent)
        }
        g.font = PlotStyle.LABEL_FONT
        g.color = PlotStyle.TEXT
        val timeLabel = "time (s)"
        val labelMetrics = g.fontMetrics
        g.drawString(timeLabel, area.left + (area.width - labelMetrics.stringWidth(timeLabel)) / 2, area.bottom + 26 + labelMetrics.ascent)
    }

    /**
     * Draws the value side of [area]: horizontal grid lines at [valueTicks] (the zero line darker), the
     * frame, tick marks and labels on the left and [valueLabel] rotated beside them. Plots whose x axis is
     * not time (categories, say) draw their own x axis after this.
     */
    fun valueAxis(g: Graphics2D, area: PlotArea, valueTicks: Ticks, valueLabel: String) {
        val line = Line2D.Double()
        g.stroke = PlotStyle.THIN
        g.color = PlotStyle.GRID
        for (v in valueTicks.values) g.draw(line.also { it.setLine(area.left.toDouble(), area.y(v), area.right.toDouble(), area.y(v)) })
        if (area.minValue < 0.0 && area.maxValue > 0.0) {
            g.color = PlotStyle.AXIS
            g.draw(line.also { it.setLine(area.left.toDouble(), area.y(0.0), area.right.toDouble(), area.y(0.0)) })
        }
        g.color = PlotStyle.AXIS
        g.drawRect(area.left, area.top, area.width, area.height)

        g.font = PlotStyle.TICK_FONT
        val metrics = g.fontMetrics
        for (v in valueTicks.values) {
            val y = area.y(v)
            g.color = PlotStyle.AXIS
            g.draw(line.also { it.setLine(area.left - 5.0, y, area.left.toDouble(), y) })
            val label = valueTicks.label(v)
            g.color = PlotStyle.MUTED_TEXT
            g.drawString(label, area.left - 8 - metrics.stringWidth(label), (y + metrics.ascent / 2.0 - 1).roundToInt())
        }

        g.font = PlotStyle.LABEL_FONT
        g.color = PlotStyle.TEXT
        val labelMetrics = g.fontMetrics
        val saved = g.transform
        g.translate(area.left - 52.0, area.top + (area.height + labelMetrics.stringWidth(valueLabel)) / 2.0)
        g.rotate(-Math.PI / 2)
        g.drawString(valueLabel, 0, 0)
        g.transform = saved
    }

    /** Draws [title] in bold with its baseline at ([x], [y]), and [subtitle] on the line below. */
    fun title(g: Graphics2D, x: Int, y: Int, title: String, subtitle: String?) {
        g.color = PlotStyle.TEXT
        g.font = PlotStyle.TITLE_FONT
        g.drawString(title, x, y)
        if (subtitle != null) {
            g.font = PlotStyle.SUBTITLE_FONT
            g.color = PlotStyle.MUTED_TEXT
            g.drawString(subtitle, x, y + 21)
        }
    }

    /** Draws [entries] stacked, right-aligned to [right], the first baseline at [y]. */
    fun legend(g: Graphics2D, right: Int, y: Int, entries: List<LegendEntry>) {
        g.font = PlotStyle.LABEL_FONT
        val metrics = g.fontMetrics
        val textWidth = entries.maxOf { metrics.stringWidth(it.label) }
        val x = right - textWidth - SWATCH - 8
        for ((i, entry) in entries.withIndex()) {
            val baseline = y + i * (metrics.height + 2)
            val middle = baseline - metrics.ascent / 2.0 + 1
            g.color = entry.color
            if (entry.band) {
                g.fillRect(x, (middle - 5).roundToInt(), SWATCH, 10)
            } else {
                g.stroke = PlotStyle.CURVE
                g.draw(Line2D.Double(x.toDouble(), middle, x + SWATCH.toDouble(), middle))
            }
            g.color = PlotStyle.TEXT
            g.drawString(entry.label, x + SWATCH + 8, baseline)
        }
    }

    private const val SWATCH = 26
}
