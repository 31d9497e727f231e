package org.hapticon.gesture.recognition

/**
 * Trains a [GestureModel] from a few labelled examples of one person (say five per label): windows them by
 * [window] and grows a forest with [params]. Examples shorter than a window contribute nothing.
 */
public class PersonalTrainer(
    public val window: WindowConfig = WindowConfig(),
    public val params: ForestParams = ForestParams(),
) {
    /**
     * A model for [examples], which must share channels and sample rate. Its labels are those present among
     * the windows, in [GestureLabel.ALL] order. [IllegalArgumentException] when no example is a window long.
     */
    public fun train(examples: List<LabelledRecording>): GestureModel {
        val first = examples.firstOrNull()?.recording ?: throw IllegalArgumentException("no examples to train on")
        val windows = LabelledWindows.of(examples, window)
        require(windows.size > 0) {
            "no example is as long as a ${window.windowSeconds} s window (${window.windowFrames(first.sampleRate)} frames)"
        }
        return train(windows, first.channels.map { it.name }, first.sampleRate)
    }

    /** A model from already windowed [windows] of [channels] at [sampleRate] Hz (windows made with [window]). */
    public fun train(windows: LabelledWindows, channels: List<String>, sampleRate: Double): GestureModel {
        require(windows.size > 0) { "no windows to train on" }
        val labels = windows.labels.toSet().sortedBy { it.index }
        val classOf = labels.withIndex().associate { (i, label) -> label to i }
        val classes = IntArray(windows.size) { classOf.getValue(windows.labels[it]) }
        val forest = RandomForest.train(windows.features, classes, labels.size, params)
        return GestureModel(sampleRate, channels, window, labels, forest)
    }
}
