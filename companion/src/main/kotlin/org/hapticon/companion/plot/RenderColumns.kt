package org.hapticon.companion.plot

import org.hapticon.core.render.IconRenderer
import kotlin.math.sqrt

/**
 * An icon render reduced to pixel columns: [waveform] (envelope × carrier, as the stream yields it) and
 * [envelope], plus the envelope's [peak] and [rms] over all samples (0 for an empty render).
 */
class RenderColumns private constructor(
    val waveform: ColumnExtremes,
    val envelope: ColumnExtremes,
    val peak: Double,
    val rms: Double,
) {
    companion object {
        /** Samples read per block: the only part of the signal held at any time. */
        const val BLOCK_SAMPLES: Int = 4096

        /**
         * Streams [renderer] once, block by block, into the columns of [area]: sample i is placed at time
         * i / sampleRate, like the axis ticks.
         */
        fun scan(renderer: IconRenderer, area: PlotArea): RenderColumns {
            val waveform = ColumnExtremes(area.width)
            val envelope = ColumnExtremes(area.width)
            val pixelsPerSample = area.width / (area.seconds * renderer.sampleRate)
            val total = renderer.sampleCount
            val stream = renderer.stream()
            val block = FloatArray(BLOCK_SAMPLES)
            var index = 0L
            var peak = 0.0
            var sumOfSquares = 0.0
            while (true) {
                val count = stream.read(block)
                if (count < 0) break
                for (j in 0 until count) {
                    val x = index * pixelsPerSample
                    val level = renderer.envelopeAt(index)
                    waveform.add(x, block[j].toDouble())
                    envelope.add(x, level)
                    peak = maxOf(peak, level)
                    sumOfSquares += level * level
                    index++
                }
            }
            val rms = if (total == 0L) 0.0 else sqrt(sumOfSquares / total)
            return RenderColumns(waveform, envelope, peak, rms)
        }
    }
}
