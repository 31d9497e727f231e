package org.hapticon.companion.gesture

import org.hapticon.companion.plot.Axes
import org.hapticon.companion.plot.LegendEntry
import org.hapticon.companion.plot.PlotStyle
import org.hapticon.companion.plot.Ticks
import java.awt.Color
import java.awt.Graphics2D
import java.awt.geom.Ellipse2D
import java.awt.geom.Line2D
import java.awt.image.BufferedImage

/**
 * `classify-bench.png`: two panels over window length (s) — leave-one-participant-out window accuracy (mean
 * ± SD bars) with the live hit rate dashed, and live decision latency (ms) — one colour per tree count.
 */
object RecognitionPlot {
    const val WIDTH: Int = 1000
    const val PANEL_HEIGHT: Int = 330
    private const val LEFT = 84
    private const val TOP = 70
    private val DASHED = java.awt.BasicStroke(2f, java.awt.BasicStroke.CAP_BUTT, java.awt.BasicStroke.JOIN_ROUND, 10f, floatArrayOf(8f, 6f), 0f)
    private val COLORS = listOf(Color(31, 119, 180), Color(245, 130, 20), Color(44, 160, 44), Color(200, 30, 45))

    /** Draws [results] of [config]. */
    fun draw(results: List<RecognitionResult>, config: RecognitionBenchConfig): BufferedImage {
        val (image, g) = PlotStyle.canvas(WIDTH, TOP + 2 * PANEL_HEIGHT)
        try {
            Axes.title(g, LEFT, 30, "Gesture recognition: window length vs accuracy and latency",
                "leave-one-participant-out, ${config.people} simulated people, 9 labels, hop 0.1 s")
            val latencies = results.map { it.latencyMs }.filter { !it.isNaN() }
            // Start the accuracy axis at a round tenth below the worst mean − SD, so differences stay visible.
            val lowest = results.minOf { minOf(it.accuracyMean - it.accuracySd, it.liveHitRate) }
            val accuracyMin = (Math.floor(lowest * 10) / 10).coerceIn(0.0, 0.9)
            panel(g, 0, results, config, "accuracy (solid: windows ± SD, dashed: live hits)", accuracyMin, 1.0, dashed = { it.liveHitRate }) { it.accuracyMean to it.accuracySd }
            panel(g, 1, results, config, "live latency from onset (ms)", 0.0, maxOf(100.0, (latencies.maxOrNull() ?: 0.0) * 1.1)) { it.latencyMs to 0.0 }
            Axes.legend(g, WIDTH - 32, 28, config.treeCounts.mapIndexed { i, t -> LegendEntry("$t trees", COLORS[i % COLORS.size]) })
        } finally {
            g.dispose()
        }
        return image
    }

    private fun panel(
        g: Graphics2D, index: Int, results: List<RecognitionResult>, config: RecognitionBenchConfig,
        label: String, min: Double, max: Double, dashed: ((RecognitionResult) -> Double)? = null,
        value: (RecognitionResult) -> Pair<Double, Double>,
    ) {
        val top = TOP + index * PANEL_HEIGHT + 10
        val height = PANEL_HEIGHT - 80
        val width = WIDTH - LEFT - 32
        val maxWindow = config.windows.max() * 1.05
        fun x(seconds: Double) = LEFT + seconds / maxWindow * width
        fun y(v: Double) = top + (max - v) / (max - min) * height
        val line = Line2D.Double()
        val ticks = Ticks.between(min, max, maxTicks = 6)
        g.font = PlotStyle.TICK_FONT
        for (v in ticks.values) {
            g.color = PlotStyle.GRID
            g.draw(line.also { it.setLine(LEFT.toDouble(), y(v), (LEFT + width).toDouble(), y(v)) })
            g.color = PlotStyle.MUTED_TEXT
            val text = ticks.label(v)
            g.drawString(text, LEFT - 8 - g.fontMetrics.stringWidth(text), (y(v) + 4).toInt())
        }
        for (w in config.windows) {
            g.color = PlotStyle.GRID
            g.draw(line.also { it.setLine(x(w), top.toDouble(), x(w), (top + height).toDouble()) })
            g.color = PlotStyle.MUTED_TEXT
            g.drawString("$w", (x(w) - 10).toInt(), top + height + 18)
        }
        g.color = PlotStyle.AXIS
        g.drawRect(LEFT, top, width, height)
        g.font = PlotStyle.LABEL_FONT
        g.color = PlotStyle.TEXT
        g.drawString("window length (s)", LEFT + width / 2 - 50, top + height + 40)
        g.drawString(label, 10, top - 6)
        g.clip = java.awt.Rectangle(LEFT, top, width + 1, height + 1)
        for ((i, trees) in config.treeCounts.withIndex()) {
            g.color = COLORS[i % COLORS.size]
            if (dashed != null) {
                g.stroke = DASHED
                val points = results.filter { it.trees == trees }.map { x(it.windowSeconds) to y(dashed(it)) }
                for ((a, b) in points.zipWithNext()) g.draw(line.also { it.setLine(a.first, a.second, b.first, b.second) })
            }
            g.stroke = PlotStyle.CURVE
            val points = results.filter { it.trees == trees && !value(it).first.isNaN() }.map { Triple(x(it.windowSeconds), value(it).first, value(it).second) }
            for ((a, b) in points.zipWithNext()) g.draw(line.also { it.setLine(a.first, y(a.second), b.first, y(b.second)) })
            for ((px, v, sd) in points) {
                g.fill(Ellipse2D.Double(px - 4, y(v) - 4, 8.0, 8.0))
                if (sd > 0.0) g.draw(line.also { it.setLine(px + i * 3, y(v - sd), px + i * 3, y(v + sd)) })
            }
        }
        g.clip = null
    }
}
