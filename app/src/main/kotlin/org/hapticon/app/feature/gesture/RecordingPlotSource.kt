package org.hapticon.app.feature.gesture

import org.hapticon.gesture.Recording
import org.hapticon.sensor.live.PlotSource

/**
 * A whole recorded take as a [PlotSource], so the trim view draws it with the same [org.hapticon.app.ui.LivePlot]
 * as the live stream: x runs over the entire take whatever window is asked for, and a take longer than
 * the output arrays is shown by every n-th frame.
 */
class RecordingPlotSource(private val recording: Recording) : PlotSource {
    override fun copyRecent(channel: Int, windowNanos: Long, xOut: FloatArray, yOut: FloatArray): Int {
        if (channel !in recording.channels.indices) return 0
        val frames = recording.frameCount
        val limit = minOf(xOut.size, yOut.size)
        if (frames == 0 || limit == 0) return 0
        val column = recording.channels[channel]
        val count = minOf(frames, limit)
        val last = (frames - 1).coerceAtLeast(1)
        for (k in 0 until count) {
            val i = if (count == 1) 0 else (k.toLong() * (frames - 1) / (count - 1)).toInt()
            xOut[k] = i.toFloat() / last
            yOut[k] = column[i].toFloat()
        }
        return count
    }
}
