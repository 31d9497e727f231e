package org.hapticon.app.ui

import androidx.compose.foundation.Canvas
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.material3.MaterialTheme
import androidx.compose.runtime.Composable
import androidx.compose.runtime.remember
import androidx.compose.ui.Modifier
import androidx.compose.ui.graphics.Path
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
        val stepX = size.width / (outline.size - 1)
        val y = { v: Float -> size.height * (1f - v.coerceIn(0f, 1f)) }
        val edge = Path().apply {
            moveTo(0f, y(outline[0]))
            for (i in 1 until outline.size) lineTo(i * stepX, y(outline[i]))
        }
        val area = Path().apply {
            addPath(edge)
            lineTo(size.width, size.height)
            lineTo(0f, size.height)
            close()
        }
        drawPath(area, fill, style = Fill)
        drawPath(edge, line, style = Stroke(width = 2.dp.toPx()))
    }
}
