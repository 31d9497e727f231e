package org.hapticon.companion.plot

import org.hapticon.core.pattern.FrequencyMapping
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.driveEnvelope
import org.hapticon.core.pattern.signal
import org.hapticon.core.render.stream
import java.awt.Color
import java.awt.geom.Ellipse2D
import java.awt.image.BufferedImage
import java.util.Locale
import kotlin.math.max

/**
 * The picture `hapticon plot` draws for a pattern: above, the drive envelope (amplitude curve plus transients,
 * ±) over the rendered waveform; below, the carrier frequency in Hz with every transient as a dot at the
 * frequency its sharpness maps to ([FrequencyMapping]). Both share the time axis. The waveform is streamed once
 * into pixel columns, so long patterns cost no memory.
 */
object PatternPlot {
    const val WIDTH: Int = 1200
    const val HEIGHT: Int = 820

    /** The frequency curve. */
    val FREQUENCY: Color = Color(60, 120, 60)

    /** A transient's dot. */
    val TAP: Color = Color(120, 40, 160)

    /** Where the amplitude (first) and the frequency (second) panels go for [pattern]. */
    fun areas(pattern: HapticPattern, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): Pair<PlotArea, PlotArea> {
        val seconds = max(pattern.duration, 0.001)
        val top = PlotArea(left = 84, top = 88, width = WIDTH - 84 - 32, height = 380, seconds = seconds, minValue = -1.1, maxValue = 1.1)
        val hertz = pattern.frequency.map { it.hertz } + pattern.transients.map { mapping.hertzOfSharpness(it.sharpness) }
        val (low, high) = hertzRange(hertz.min(), hertz.max())
        return top to PlotArea(left = 84, top = top.bottom + 60, width = top.width, height = 200, seconds = seconds, minValue = low, maxValue = high)
    }

    /** Draws [pattern] rendered at [sampleRate] with [mapping] (which places the transients' carriers). */
    fun draw(pattern: HapticPattern, sampleRate: Int, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): BufferedImage {
        val (top, bottom) = areas(pattern, mapping)
        val seconds = top.seconds
        val low = bottom.minValue
        val high = bottom.maxValue
        val tapHertz = pattern.transients.map { mapping.hertzOfSharpness(it.sharpness) }
        val waveform = ColumnExtremes(top.width)
        val envelope = ColumnExtremes(top.width)
        val drive = pattern.driveEnvelope()
        val stream = pattern.signal(mapping).stream(sampleRate)
        val block = FloatArray(RenderColumns.BLOCK_SAMPLES)
        val pixelsPerSample = top.width / (seconds * sampleRate)
        var index = 0L
        while (true) {
            val count = stream.read(block)
            if (count < 0) break
            for (j in 0 until count) {
                val x = index * pixelsPerSample
                waveform.add(x, block[j].toDouble())
                envelope.add(x, drive(index.toDouble() / sampleRate))
                index++
            }
        }
        val (image, g) = PlotStyle.canvas(WIDTH, HEIGHT)
        try {
            Axes.draw(g, top, Ticks.between(-1.0, 1.0, maxTicks = 5), "amplitude")
            drawEnvelopeOverWaveform(g, top, waveform, envelope)

            Axes.draw(g, bottom, Ticks.between(low, high, maxTicks = 5), "frequency (Hz)")
            g.clip = java.awt.Rectangle(bottom.left, bottom.top, bottom.width + 1, bottom.height + 1)
            g.stroke = PlotStyle.CURVE
            g.color = FREQUENCY
            val curve = ColumnExtremes(bottom.width)
            for (c in 0..bottom.width) {
                val t = seconds * c / bottom.width
                curve.add(c.toDouble(), pattern.frequencyAt(t))
            }
            curve.draw(g, bottom)
            g.color = TAP
            for ((tap, hz) in pattern.transients.zip(tapHertz)) {
                g.fill(Ellipse2D.Double(bottom.x(tap.time) - 4, bottom.y(hz) - 4, 8.0, 8.0))
            }
            g.clip = null

            val lowest = pattern.frequency.minOf { it.hertz }
            val highest = pattern.frequency.maxOf { it.hertz }
            val pitch = if (lowest == highest) String.format(Locale.ROOT, "%.0f Hz", lowest) else String.format(Locale.ROOT, "%.0f–%.0f Hz", lowest, highest)
            val subtitle = String.format(
                Locale.ROOT, "%.3f s · %d amplitude keys · %d frequency keys · %d transient%s · %s",
                pattern.duration, pattern.amplitude.size, pattern.frequency.size, pattern.transients.size,
                if (pattern.transients.size == 1) "" else "s", pitch,
            )
            Axes.title(g, top.left, 32, "${pattern.name} · pattern · $sampleRate Hz", subtitle)
            Axes.legend(
                g, top.right, 22,
                listOf(
                    LegendEntry("drive envelope (±)", PlotStyle.ENVELOPE),
                    LegendEntry("envelope × carrier", PlotStyle.WAVEFORM, band = true),
                    LegendEntry("carrier frequency", FREQUENCY),
                    LegendEntry("transient (sharpness → Hz)", TAP, band = true),
                ),
            )
        } finally {
            g.dispose()
        }
        return image
    }

    /** A frequency axis range around [min]..[max] with 10 % room, never empty (a constant carrier gets ±10 %). */
    private fun hertzRange(min: Double, max: Double): Pair<Double, Double> {
        if (max <= min) return maxOf(0.0, min - 0.1 * max) to max + 0.1 * max
        val span = max - min
        return maxOf(0.0, min - 0.1 * span) to max + 0.1 * span
    }
}
