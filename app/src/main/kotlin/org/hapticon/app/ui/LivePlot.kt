package org.hapticon.app.ui

import androidx.compose.foundation.Canvas
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.material3.MaterialTheme
import androidx.compose.runtime.Composable
import androidx.compose.runtime.remember
import androidx.compose.ui.Modifier
import androidx.compose.ui.geometry.Offset
import androidx.compose.ui.graphics.Path
import androidx.compose.ui.graphics.drawscope.Stroke
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.Dp
import androidx.compose.ui.unit.dp
import org.hapticon.sensor.live.PlotSource

/** How much of the past a live plot shows. */
const val PLOT_WINDOW_SECONDS: Int = 5

/**
 * A compact line plot of one channel's last [PLOT_WINDOW_SECONDS] seconds, scaled to its own range.
 * Draws straight from [source] into a reused path and reused arrays: nothing is allocated per frame.
 * [revision] changes when new samples arrived, which redraws it.
 */
@Composable
fun LivePlot(
    source: PlotSource,
    channel: Int,
    revision: Long,
    label: String,
    modifier: Modifier = Modifier,
    height: Dp = 40.dp,
    /** What a screen reader says; a source that is not a live window (a whole recording) says so here. */
    description: String = "Plot of $label over the last $PLOT_WINDOW_SECONDS seconds",
) {
    val xs = remember { FloatArray(MAX_POINTS) }
    val ys = remember { FloatArray(MAX_POINTS) }
    val path = remember { Path() }
    val line = MaterialTheme.colorScheme.primary
    val axis = MaterialTheme.colorScheme.outlineVariant
    Canvas(
        modifier
            .fillMaxWidth()
            .height(height)
            .semantics { contentDescription = description },
    ) {
        drawLine(axis, start = Offset(0f, size.height), end = Offset(size.width, size.height))
        // revision is captured so that a new one redraws; the points come from the source.
        val n = if (revision < 0) 0 else source.copyRecent(channel, PLOT_WINDOW_SECONDS * 1_000_000_000L, xs, ys)
        if (n == 0) return@Canvas
        var min = Float.POSITIVE_INFINITY
        var max = Float.NEGATIVE_INFINITY
        for (i in 0 until n) {
            val y = ys[i]
            if (y.isNaN()) continue
            if (y < min) min = y
            if (y > max) max = y
        }
        if (min > max) return@Canvas
        val span = if (max > min) max - min else 1f
        val base = if (max > min) min else min - 0.5f
        val inset = 2.dp.toPx()
        val h = size.height - 2 * inset
        path.rewind()
        var started = false
        for (i in 0 until n) {
            val y = ys[i]
            if (y.isNaN()) {
                started = false
                continue
            }
            val px = xs[i] * size.width
            val py = inset + h * (1f - (y - base) / span)
            if (started) path.lineTo(px, py) else path.moveTo(px, py)
            started = true
        }
        drawPath(path, line, style = Stroke(width = 1.5.dp.toPx()))
    }
}

/** Points drawn at most: the history's capacity. */
private const val MAX_POINTS = 4096
