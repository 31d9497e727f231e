package org.hapticon.companion.study

import org.hapticon.companion.plot.Axes
import org.hapticon.companion.plot.PlotArea
import org.hapticon.companion.plot.PlotStyle
import org.hapticon.companion.plot.Ticks
import org.hapticon.study.analysis.Descriptives
import java.awt.BasicStroke
import java.awt.Color
import java.awt.Graphics2D
import java.awt.geom.Ellipse2D
import java.awt.geom.Line2D
import java.awt.geom.Path2D
import java.awt.geom.Rectangle2D
import java.awt.image.BufferedImage
import kotlin.math.ceil
import kotlin.math.floor
import kotlin.math.max
import kotlin.math.min
import kotlin.math.roundToInt

/**
 * One task's box plot: one box per icon over a Likert axis (1..5, widened if responses fall outside).
 * Box from q1 to q3 (R type 7 quartiles, as in descriptives.csv), median line, whiskers to the most
 * extreme response within 1.5·IQR of the box, responses beyond as outlier dots, mean as a diamond.
 */
object StudyBoxPlot {
    const val HEIGHT: Int = 440
    private const val LEFT = 76
    private const val TOP = 78
    private const val RIGHT_MARGIN = 24
    private const val BOTTOM_MARGIN = 64
    private const val COLUMN_WIDTH = 120
    private const val MIN_WIDTH = 480

    /** The box of one icon: its [descriptives] and the whisker ends and [outliers] derived from [values]. */
    class IconBox(val icon: String, val descriptives: Descriptives, val lowWhisker: Double, val highWhisker: Double, val outliers: List<Double>) {
        companion object {
            /** The box of [values] (non-empty, finite) for [icon]. */
            fun of(icon: String, values: List<Double>): IconBox {
                val d = Descriptives.of(values)
                val low = d.q1 - 1.5 * d.iqr
                val high = d.q3 + 1.5 * d.iqr
                val inside = values.filter { it in low..high }
                return IconBox(icon, d, inside.min(), inside.max(), values.filter { it !in low..high }.sorted())
            }
        }
    }

    /** Image width for [icons] boxes. */
    fun width(icons: Int): Int = max(MIN_WIDTH, LEFT + RIGHT_MARGIN + icons * COLUMN_WIDTH)

    /** Where the data of [boxes] goes: x in box units (box i centred at i + 0.5), y in response units. */
    fun area(boxes: List<IconBox>): PlotArea {
        val low = min(LIKERT_MIN, floor(boxes.minOf { it.descriptives.min }))
        val high = max(LIKERT_MAX, ceil(boxes.maxOf { it.descriptives.max }))
        val width = width(boxes.size)
        return PlotArea(LEFT, TOP, width - LEFT - RIGHT_MARGIN, HEIGHT - TOP - BOTTOM_MARGIN, boxes.size.toDouble(), low - 0.5, high + 0.5)
    }

    /** Draws [boxes] for [task] ([participants] people). */
    fun draw(task: String, participants: Int, boxes: List<IconBox>): BufferedImage {
        require(boxes.isNotEmpty()) { "no icons to plot for task '$task'" }
        val area = area(boxes)
        val (image, g) = PlotStyle.canvas(width(boxes.size), HEIGHT)
        try {
            Axes.title(g, LEFT, 30, "Task: $task", "$participants participants · box IQR, line median, ◆ mean, whiskers 1.5·IQR")
            drawAxes(g, area, boxes)
            for ((i, box) in boxes.withIndex()) drawBox(g, area, i, box)
        } finally {
            g.dispose()
        }
        return image
    }

    private fun drawAxes(g: Graphics2D, area: PlotArea, boxes: List<IconBox>) {
        // One tick per scale point (Likert values are whole numbers), fewer on long scales.
        val ticks = Ticks.between(area.minValue, area.maxValue, maxTicks = (area.maxValue - area.minValue).toInt().plus(1).coerceIn(2, 12))
        Axes.valueAxis(g, area, ticks, "response")
        g.font = PlotStyle.LABEL_FONT
        val labelMetrics = g.fontMetrics
        g.color = PlotStyle.TEXT
        for ((i, box) in boxes.withIndex()) {
            val label = "${box.icon} (n=${box.descriptives.n})"
            g.drawString(label, (area.x(i + 0.5) - labelMetrics.stringWidth(label) / 2.0).roundToInt(), area.bottom + 8 + labelMetrics.ascent)
        }
    }

    private fun drawBox(g: Graphics2D, area: PlotArea, index: Int, box: IconBox) {
        val d = box.descriptives
        val centre = area.x(index + 0.5)
        val half = BOX_HALF_WIDTH
        g.stroke = PlotStyle.CURVE
        g.color = PlotStyle.AXIS
        // Whiskers: a vertical line from each box edge to its end, with a short cap.
        g.draw(Line2D.Double(centre, area.y(d.q3), centre, area.y(box.highWhisker)))
        g.draw(Line2D.Double(centre, area.y(d.q1), centre, area.y(box.lowWhisker)))
        g.draw(Line2D.Double(centre - half / 2, area.y(box.highWhisker), centre + half / 2, area.y(box.highWhisker)))
        g.draw(Line2D.Double(centre - half / 2, area.y(box.lowWhisker), centre + half / 2, area.y(box.lowWhisker)))
        val rect = Rectangle2D.Double(centre - half, area.y(d.q3), 2 * half, area.y(d.q1) - area.y(d.q3))
        g.color = BOX_FILL
        g.fill(rect)
        g.color = PlotStyle.PAPER
        g.draw(rect)
        g.stroke = MEDIAN_STROKE
        g.color = MEDIAN
        g.draw(Line2D.Double(centre - half, area.y(d.median), centre + half, area.y(d.median)))
        g.color = PlotStyle.TEXT
        for (value in box.outliers) g.fill(Ellipse2D.Double(centre - 3.5, area.y(value) - 3.5, 7.0, 7.0))
        val y = area.y(d.mean)
        val diamond = Path2D.Double().apply {
            moveTo(centre, y - 6); lineTo(centre + 6, y); lineTo(centre, y + 6); lineTo(centre - 6, y); closePath()
        }
        g.color = MEAN
        g.fill(diamond)
    }

    /** Half the width of a box in pixels. */
    const val BOX_HALF_WIDTH: Double = 30.0

    /** The median line. */
    val MEDIAN: Color = PlotStyle.ENVELOPE

    /** The mean diamond. */
    val MEAN: Color = PlotStyle.PROCESSING

    /** The inside of a box. */
    val BOX_FILL: Color = Color(205, 225, 245)

    private val MEDIAN_STROKE = BasicStroke(3f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_MITER)
    private const val LIKERT_MIN = 1.0
    private const val LIKERT_MAX = 5.0
}
