package org.hapticon.app.gesture

import org.hapticon.gesture.Recording
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.recognition.GestureModel
import org.hapticon.gesture.recognition.LabelledRecording
import org.hapticon.gesture.recognition.LabelledSpan
import org.hapticon.gesture.recognition.LabelledWindows
import kotlin.math.abs

/**
 * Where the gesture is in a teach example ("rest, do it once, rest"), so that only the gesture is learned
 * as the gesture and the rest around it as none — what `hapticon train` asks of trimmed files.
 */
object GestureSpans {
    /** A frame is active when it is this share of the channel's largest deviation from rest away from rest. */
    const val ACTIVE_SHARE: Double = 0.2

    /** Frames kept around the active part, in seconds (the gesture's soft start and end). */
    const val PAD_SECONDS: Double = 0.1

    /** The start of a take that is taken as rest (the take begins with the hand at rest), in seconds. */
    const val REST_SECONDS: Double = 0.25

    /**
     * The frames `[from, to)` of [recording] that hold the gesture. Rest is the first [REST_SECONDS]: its
     * median per channel is the rest value and its median absolute deviation the noise. On the channel that
     * moves furthest from rest relative to its noise, the gesture runs from the first to the last frame at
     * least [ACTIVE_SHARE] of the largest deviation away, padded by [PAD_SECONDS]. Null when no channel
     * moves at all (a constant recording) or the take is not longer than its rest.
     */
    fun find(recording: Recording): IntRange? {
        val restFrames = maxOf(1, (REST_SECONDS * recording.sampleRate).toInt())
        if (recording.frameCount <= restFrames) return null
        var best: DoubleArray? = null
        var bestScore = 0.0
        for (channel in recording.channels) {
            val samples = channel.toDoubleArray()
            if (samples.any { !it.isFinite() }) continue
            val rest = median(samples.copyOf(restFrames))
            val deviation = DoubleArray(samples.size) { abs(samples[it] - rest) }
            val noise = median(deviation.copyOf(restFrames))
            val peak = deviation.max()
            if (peak <= 0.0) continue
            // Peak over noise; a channel that is flat at rest but moves (noise 0) wins outright.
            val score = if (noise > 0.0) peak / noise else Double.MAX_VALUE
            if (score > bestScore) {
                bestScore = score
                best = deviation
            }
        }
        val deviation = best ?: return null
        val threshold = ACTIVE_SHARE * deviation.max()
        val first = deviation.indexOfFirst { it >= threshold }
        val last = deviation.indexOfLast { it >= threshold }
        val pad = (PAD_SECONDS * recording.sampleRate).toInt()
        return maxOf(0, first - pad) until minOf(recording.frameCount, last + 1 + pad)
    }

    /** [recording] as a teach example of [label]: all rest for [GestureLabel.NONE], else the [find] span (the whole clip when none is found). */
    fun label(recording: Recording, label: GestureLabel): LabelledRecording {
        if (label.isNone) return LabelledRecording(recording, emptyList())
        val span = find(recording) ?: (0 until recording.frameCount)
        return LabelledRecording(recording, listOf(LabelledSpan(span.first, span.last + 1, label)))
    }

    /** Share of [windows] that [model] labels right (0 for no windows). */
    fun accuracy(model: GestureModel, windows: LabelledWindows): Double {
        if (windows.size == 0) return 0.0
        val probabilities = DoubleArray(model.labels.size)
        var right = 0
        for (i in 0 until windows.size) {
            if (model.labels[model.forest.predict(windows.features[i], probabilities)] == windows.labels[i]) right++
        }
        return right.toDouble() / windows.size
    }

    private fun median(values: DoubleArray): Double {
        val sorted = values.sortedArray()
        val mid = sorted.size / 2
        return if (sorted.size % 2 == 1) sorted[mid] else (sorted[mid - 1] + sorted[mid]) / 2
    }
}
