package org.hapticon.gesture.recognition

import org.hapticon.gesture.Recording
import kotlin.math.abs

/** Frames `[from, to)` of a recording show [label]. */
public class LabelledSpan(public val from: Int, public val to: Int, public val label: GestureLabel) {
    init {
        require(from in 0 until to) { "span [$from, $to) must be non-empty and start at >= 0" }
    }

    override fun toString(): String = "$label[$from, $to)"
}

/**
 * A [recording] whose gestures are marked by [spans] (non-overlapping); frames outside every span are
 * [GestureLabel.NONE]. Use [whole] for a clip that is one gesture from start to end.
 */
public class LabelledRecording(public val recording: Recording, public val spans: List<LabelledSpan>) {
    init {
        val sorted = spans.sortedBy { it.from }
        for (span in sorted) require(span.to <= recording.frameCount) { "span $span ends after the recording's ${recording.frameCount} frames" }
        for (i in 1 until sorted.size) require(sorted[i].from >= sorted[i - 1].to) { "spans ${sorted[i - 1]} and ${sorted[i]} overlap" }
    }

    /**
     * The label of the window `[from, from + frames)`: a span's label when the window holds at least half of
     * the span or the span fills at least half of the window (so a 0.1 s hit labels a 2 s window around it);
     * [GestureLabel.NONE] when it touches no span of a gesture; null (ambiguous: neither, so not used for
     * training or scoring) otherwise.
     */
    public fun windowLabel(from: Int, frames: Int): GestureLabel? {
        val to = from + frames
        var touched = false
        var best: GestureLabel? = null
        var bestOverlap = 0
        for (span in spans) {
            val overlap = minOf(to, span.to) - maxOf(from, span.from)
            if (overlap <= 0 || span.label.isNone) continue
            touched = true
            if (2 * overlap >= minOf(frames, span.to - span.from) && overlap > bestOverlap) {
                best = span.label
                bestOverlap = overlap
            }
        }
        return best ?: if (touched) null else GestureLabel.NONE
    }

    override fun toString(): String = "LabelledRecording($recording, $spans)"

    public companion object {
        /** [recording] showing [label] throughout. */
        public fun whole(recording: Recording, label: GestureLabel): LabelledRecording =
            LabelledRecording(recording, listOf(LabelledSpan(0, recording.frameCount, label)))
    }
}

/** Feature rows of labelled windows and their labels (index-aligned), as [PersonalTrainer] trains on them. */
public class LabelledWindows(public val features: List<DoubleArray>, public val labels: List<GestureLabel>) {
    init {
        require(features.size == labels.size) { "${features.size} feature rows but ${labels.size} labels" }
    }

    /** Number of windows. */
    public val size: Int get() = labels.size

    /** These windows followed by [other]'s. */
    public operator fun plus(other: LabelledWindows): LabelledWindows = LabelledWindows(features + other.features, labels + other.labels)

    public companion object {
        /**
         * Every window of [window] (stepping by its hop) of each example whose [LabelledRecording.windowLabel]
         * is not ambiguous. [IllegalArgumentException] when the examples differ in channels or in sample rate
         * by more than 0.1 %.
         */
        public fun of(examples: List<LabelledRecording>, window: WindowConfig): LabelledWindows {
            require(examples.isNotEmpty()) { "no examples" }
            val first = examples[0].recording
            val names = first.channels.map { it.name }
            for (example in examples) {
                val r = example.recording
                require(r.channels.map { it.name } == names) { "examples must share channels: $names vs ${r.channels.map { it.name }}" }
                // Rates measured from CSV time stamps differ in the last digits; 0.1 % is far below any real mismatch.
                require(abs(r.sampleRate - first.sampleRate) <= first.sampleRate * 1e-3) { "examples must share a sample rate: ${first.sampleRate} vs ${r.sampleRate} Hz" }
            }
            val frames = window.windowFrames(first.sampleRate)
            val hop = window.hopFrames(first.sampleRate)
            val extractor = WindowFeatures(first.sampleRate, frames)
            val features = ArrayList<DoubleArray>()
            val labels = ArrayList<GestureLabel>()
            for (example in examples) {
                val data = example.recording.channels.map { it.toDoubleArray() }
                var from = 0
                while (from + frames <= example.recording.frameCount) {
                    val label = example.windowLabel(from, frames)
                    if (label != null) {
                        val row = DoubleArray(data.size * WindowFeatures.PER_CHANNEL)
                        for ((i, samples) in data.withIndex()) extractor.extract(samples, from, frames, row, i * WindowFeatures.PER_CHANNEL)
                        features += row
                        labels += label
                    }
                    from += hop
                }
            }
            return LabelledWindows(features, labels)
        }
    }
}
