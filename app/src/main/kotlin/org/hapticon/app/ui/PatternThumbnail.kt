package org.hapticon.app.ui

import androidx.compose.foundation.Canvas
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.material3.MaterialTheme
import androidx.compose.runtime.Composable
import androidx.compose.runtime.remember
import androidx.compose.ui.Modifier
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
        drawFilledCurve(curves.amplitude, line, fill)
        if (showFrequency) drawPath(curvePath(curves.pitch), pitch, style = Stroke(width = 1.5.dp.toPx()))
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
