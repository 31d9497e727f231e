package org.hapticon.app.ui

import androidx.compose.foundation.Canvas
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.material3.MaterialTheme
import androidx.compose.runtime.Composable
import androidx.compose.runtime.remember
import androidx.compose.ui.Modifier
import androidx.compose.ui.graphics.Color
import androidx.compose.ui.graphics.Path
import androidx.compose.ui.graphics.drawscope.DrawScope
import androidx.compose.ui.graphics.drawscope.Fill
import androidx.compose.ui.graphics.drawscope.Stroke
import androidx.compose.ui.semantics.contentDescription
import androidx.compose.ui.semantics.semantics
import androidx.compose.ui.unit.dp
import org.hapticon.core.HapticIcon

private const val OUTLINE_POINTS = 160

/** A small filled plot of the icon's amplitude envelope over its whole duration. */
@Composable
fun EnvelopeThumbnail(icon: HapticIcon, modifier: Modifier = Modifier) {
    val outline = remember(icon) { envelopeOutline(icon, OUTLINE_POINTS) }
    val line = MaterialTheme.colorScheme.primary
    val fill = line.copy(alpha = 0.25f)
    Canvas(
        modifier
            .fillMaxWidth()
            .height(48.dp)
            .semantics { contentDescription = "Envelope of ${icon.name}" },
    ) {
        drawFilledCurve(outline, line, fill)
    }
}

/** [values] (0..1, evenly spaced across the width) as a [line] with the area under it in [fill]. */
internal fun DrawScope.drawFilledCurve(values: FloatArray, line: Color, fill: Color) {
    val edge = curvePath(values)
    val area = Path().apply {
        addPath(edge)
        lineTo(size.width, size.height)
        lineTo(0f, size.height)
        close()
    }
    drawPath(area, fill, style = Fill)
    drawPath(edge, line, style = Stroke(width = 2.dp.toPx()))
}

/** The polyline through [values] (0..1 upwards, evenly spaced across the width). */
internal fun DrawScope.curvePath(values: FloatArray): Path {
    val stepX = size.width / (values.size - 1)
    val y = { v: Float -> size.height * (1f - v.coerceIn(0f, 1f)) }
    return Path().apply {
        moveTo(0f, y(values[0]))
        for (i in 1 until values.size) lineTo(i * stepX, y(values[i]))
    }
}
