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
import org.hapticon.core.pattern.FrequencyMapping
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.driveEnvelope

private const val PATTERN_POINTS = 200

/**
 * A small plot of a pattern: its drive envelope (amplitude curve plus transients) filled, and, with
 * [showFrequency], its carrier frequency as a line on [FrequencyMapping.DEFAULT]'s log scale (C2 at the bottom,
 * C5 at the top), so a sweep reads as a rising or falling line.
 */
@Composable
fun PatternThumbnail(pattern: HapticPattern, modifier: Modifier = Modifier, showFrequency: Boolean = true) {
    val curves = remember(pattern) { patternCurves(pattern, PATTERN_POINTS) }
    val line = MaterialTheme.colorScheme.primary
    val fill = line.copy(alpha = 0.25f)
    val pitch = MaterialTheme.colorScheme.tertiary
    Canvas(
        modifier
            .fillMaxWidth()
            .height(48.dp)
            .semantics { contentDescription = "Envelope and pitch of ${pattern.name}" },
    ) {
        val stepX = size.width / (PATTERN_POINTS - 1)
        val y = { v: Float -> size.height * (1f - v.coerceIn(0f, 1f)) }
        val edge = Path().apply {
            moveTo(0f, y(curves.amplitude[0]))
            for (i in 1 until PATTERN_POINTS) lineTo(i * stepX, y(curves.amplitude[i]))
        }
        val area = Path().apply {
            addPath(edge)
            lineTo(size.width, size.height)
            lineTo(0f, size.height)
            close()
        }
        drawPath(area, fill, style = Fill)
        drawPath(edge, line, style = Stroke(width = 2.dp.toPx()))
        if (showFrequency) {
            val frequency = Path().apply {
                moveTo(0f, y(curves.pitch[0]))
                for (i in 1 until PATTERN_POINTS) lineTo(i * stepX, y(curves.pitch[i]))
            }
            drawPath(frequency, pitch, style = Stroke(width = 1.5.dp.toPx()))
        }
    }
}

/** The drive envelope and the normalised pitch at [points] evenly spaced times over the pattern. */
internal class PatternCurves(val amplitude: FloatArray, val pitch: FloatArray)

internal fun patternCurves(pattern: HapticPattern, points: Int): PatternCurves {
    val envelope = pattern.driveEnvelope()
    val span = pattern.duration
    val times = DoubleArray(points) { span * it / (points - 1) }
    return PatternCurves(
        FloatArray(points) { envelope(times[it]).toFloat() },
        FloatArray(points) { FrequencyMapping.DEFAULT.normalizedOf(pattern.frequencyAt(times[it])).toFloat() },
    )
}
