package org.hapticon.gesture.recognition

import java.util.SplittableRandom

/**
 * The touch-gesture pipeline of the NAO fabric-sensor paper, as a named preset beside our default
 * ([WindowConfig] defaults, [WindowFeatures]' 33 features, [ForestParams] defaults, [GestureLabel]'s nine labels):
 *
 * - **Input:** 4 resistive channels sampled at [SAMPLE_RATE] = 40 Hz.
 * - **Windows:** [WINDOW_FRAMES] = 80 samples (2 s) with 50 % overlap ([HOP_FRAMES] = 40); a window takes a
 *   gesture's label when it overlaps that gesture by at least [LABEL_OVERLAP] = 0.75 of the window's length
 *   (60 samples), else `none` ([windowLabel]). (Our default labels by "half the window or half the gesture"
 *   and leaves the rest out; see [LabelledRecording.windowLabel].)
 * - **Features:** 31 per channel ([FEATURE_INDICES]): entropy of the signal, and sum, max, min, mean, median,
 *   standard deviation, variance, area, IQR and number of peaks of the signal, its first and its second
 *   difference (1 + 3 × 10 = 31). Our 33 add the entropy of both differences; the peaks statistic is our reading
 *   of "the rest of the paper's list" (the only one left that makes 31), not re-checked against the paper's text.
 * - **Forest:** [FOREST]: 100 trees, max depth 32, 20 features per split, at least 8 samples to split, Gini,
 *   bootstrap.
 * - **Classes:** [LABELS]: hit, poke, squeeze, stroke, tickle × gentle, energetic, and none (11).
 *
 * Its own label strings are used rather than [GestureLabel] (whose gestures are the messenger's stroke, hit, knock
 * and hug): the NAO classes are a research preset evaluated offline ([NaoEvaluation]), not icons to send.
 */
public object NaoPreset {
    /** Samples per second of the fabric sensor. */
    public const val SAMPLE_RATE: Double = 40.0

    /** Resistive channels. */
    public const val CHANNELS: Int = 4

    /** Samples per window (2 s). */
    public const val WINDOW_FRAMES: Int = 80

    /** Samples between window starts: 50 % overlap. */
    public const val HOP_FRAMES: Int = 40

    /** Share of the window a gesture must cover for the window to take its label. */
    public const val LABEL_OVERLAP: Double = 0.75

    /** The label of windows that no gesture covers enough. */
    public const val NONE: String = "none"

    /** The five gestures. */
    public val GESTURES: List<String> = listOf("hit", "poke", "squeeze", "stroke", "tickle")

    /** The two intensities. */
    public val INTENSITIES: List<String> = listOf("gentle", "energetic")

    /** The 11 classes: `gesture-intensity` in [GESTURES] × [INTENSITIES] order, then [NONE]. */
    public val LABELS: List<String> = GESTURES.flatMap { g -> INTENSITIES.map { "$g-$it" } } + NONE

    /** Which of [WindowFeatures]' 33 per-channel features the paper uses, in our order (drops `d1.entropy`, `d2.entropy`). */
    public val FEATURE_INDICES: IntArray = run {
        val n = WindowFeatures.STATISTICS.size
        val entropy = WindowFeatures.STATISTICS.indexOf("entropy")
        (0 until 3 * n).filter { it < n || it % n != entropy }.toIntArray()
    }

    /** Features per channel: 31. */
    public val FEATURES_PER_CHANNEL: Int = FEATURE_INDICES.size

    /** The paper's random forest (scikit-learn: n_estimators 100, max_depth 32, max_features 20, min_samples_split 8, gini, bootstrap). */
    public val FOREST: ForestParams = ForestParams(trees = 100, maxDepth = 32, featuresPerSplit = 20, minSamplesSplit = 8, bootstrap = true)

    /** The feature names of [channels], in row order, e.g. `r1.entropy`, `r1.d1.iqr`. */
    public fun featureNames(channels: List<String>): List<String> {
        val all = WindowFeatures.names(listOf("x"))
        return channels.flatMap { c -> FEATURE_INDICES.map { "$c${all[it].removePrefix("x")}" } }
    }

    /**
     * The label of the window `[from, from + frames)`: the label of a span it overlaps by at least
     * ⌈[LABEL_OVERLAP] × frames⌉ samples (the larger overlap wins), else [NONE].
     */
    public fun windowLabel(spans: List<NaoSpan>, from: Int, frames: Int = WINDOW_FRAMES): String {
        val needed = Math.ceil(LABEL_OVERLAP * frames - 1e-9).toInt()
        var best = NONE
        var bestOverlap = 0
        for (span in spans) {
            val overlap = minOf(from + frames, span.to) - maxOf(from, span.from)
            if (overlap >= needed && overlap > bestOverlap) {
                best = span.label
                bestOverlap = overlap
            }
        }
        return best
    }

    /** Every window (hop [HOP_FRAMES]) of every recording, with the paper's features and labels. */
    public fun windows(recordings: List<NaoRecording>): NaoWindows {
        val extractor = NaoFeatures()
        val features = ArrayList<DoubleArray>()
        val labels = ArrayList<String>()
        val people = ArrayList<String>()
        for (r in recordings) {
            var from = 0
            while (from + WINDOW_FRAMES <= r.frameCount) {
                val row = DoubleArray(CHANNELS * FEATURES_PER_CHANNEL)
                extractor.extract(r.channels, from, row)
                features += row
                labels += windowLabel(r.spans, from)
                people += r.person
                from += HOP_FRAMES
            }
        }
        return NaoWindows(features, labels, people)
    }
}

/** Samples `[from, to)` of a recording show the NAO class [label] (one of [NaoPreset.LABELS] but [NaoPreset.NONE]). */
public class NaoSpan(public val from: Int, public val to: Int, public val label: String) {
    init {
        require(from in 0 until to) { "span [$from, $to) must be non-empty and start at >= 0" }
        require(label in NaoPreset.LABELS && label != NaoPreset.NONE) { "unknown NAO gesture '$label'; expected one of ${NaoPreset.LABELS.dropLast(1)}" }
    }

    override fun toString(): String = "$label[$from, $to)"
}

/** One [person]'s session: [NaoPreset.CHANNELS] equally long resistance series at 40 Hz and its gesture [spans]. */
public class NaoRecording(public val person: String, public val channels: List<DoubleArray>, public val spans: List<NaoSpan>) {
    init {
        require(channels.size == NaoPreset.CHANNELS) { "need ${NaoPreset.CHANNELS} channels, got ${channels.size}" }
        require(channels.all { it.size == channels[0].size }) { "channels differ in length: ${channels.map { it.size }}" }
        for (s in spans) require(s.to <= channels[0].size) { "span $s ends after the ${channels[0].size} samples" }
    }

    /** Samples per channel. */
    public val frameCount: Int get() = channels[0].size
}

/** Feature rows, their labels and whose they are (index-aligned). */
public class NaoWindows(public val features: List<DoubleArray>, public val labels: List<String>, public val people: List<String>) {
    init {
        require(features.size == labels.size && labels.size == people.size) { "${features.size} rows, ${labels.size} labels, ${people.size} people" }
    }

    /** Number of windows. */
    public val size: Int get() = labels.size

    /** The windows at [indices]. */
    public fun subset(indices: List<Int>): NaoWindows = NaoWindows(indices.map { features[it] }, indices.map { labels[it] }, indices.map { people[it] })
}

/**
 * The paper's 31 features of each of the 4 channels: [WindowFeatures] at 40 Hz, keeping [NaoPreset.FEATURE_INDICES].
 * Not thread-safe; allocates nothing per call.
 */
public class NaoFeatures {
    private val full = WindowFeatures(NaoPreset.SAMPLE_RATE, NaoPreset.WINDOW_FRAMES)
    private val scratch = DoubleArray(WindowFeatures.PER_CHANNEL)

    /** Writes the 4 × 31 features of the window starting at [from] into [out]. */
    public fun extract(channels: List<DoubleArray>, from: Int, out: DoubleArray) {
        require(channels.size == NaoPreset.CHANNELS) { "need ${NaoPreset.CHANNELS} channels, got ${channels.size}" }
        require(out.size == NaoPreset.CHANNELS * NaoPreset.FEATURES_PER_CHANNEL) { "out must hold ${NaoPreset.CHANNELS * NaoPreset.FEATURES_PER_CHANNEL} features" }
        for (c in channels.indices) {
            full.extract(channels[c], from, NaoPreset.WINDOW_FRAMES, scratch, 0)
            NaoPreset.FEATURE_INDICES.forEachIndexed { k, i -> out[c * NaoPreset.FEATURES_PER_CHANNEL + k] = scratch[i] }
        }
    }
}

/**
 * Accuracy of a classifier over the NAO classes, from its [confusion] matrix (rows = truth, columns = prediction,
 * both in [NaoPreset.LABELS] order).
 *
 * - [combined]: the whole label right (the paper's 74.1 %);
 * - [gesture]: the gesture part right, `none` counting as its own gesture (the paper's 74.3 %);
 * - [intensity]: among windows whose truth is a gesture, the intensity part right, a `none` prediction counting
 *   as wrong (the paper's 89.3 %). The paper may have scored gesture and intensity with separate classifiers; we
 *   derive both from the one 11-class forest.
 */
public class NaoScores(public val confusion: Array<IntArray>) {
    init {
        require(confusion.size == NaoPreset.LABELS.size && confusion.all { it.size == NaoPreset.LABELS.size }) { "need an 11 × 11 matrix" }
    }

    /** Windows scored. */
    public val total: Int get() = confusion.sumOf { it.sum() }

    /** Share of windows whose whole label is right. */
    public val combined: Double get() = share { t, p -> t == p }

    /** Share of windows whose gesture (or none) is right. */
    public val gesture: Double get() = share { t, p -> part(t, 0) == part(p, 0) }

    /** Among gesture windows, the share whose intensity is right. */
    public val intensity: Double get() {
        var right = 0
        var all = 0
        for (t in NaoPreset.LABELS.indices) for (p in NaoPreset.LABELS.indices) {
            if (NaoPreset.LABELS[t] == NaoPreset.NONE) continue
            all += confusion[t][p]
            if (part(t, 1) == part(p, 1)) right += confusion[t][p]
        }
        return if (all == 0) 0.0 else right.toDouble() / all
    }

    /** Share of [truth]'s windows predicted as [predicted] (the recall when they are equal). */
    public fun share(truth: String, predicted: String): Double {
        val t = NaoPreset.LABELS.indexOf(truth)
        val p = NaoPreset.LABELS.indexOf(predicted)
        require(t >= 0 && p >= 0) { "unknown label $truth or $predicted" }
        val row = confusion[t].sum()
        return if (row == 0) 0.0 else confusion[t][p].toDouble() / row
    }

    private fun part(index: Int, which: Int): String = NaoPreset.LABELS[index].split('-').getOrElse(which) { "" }

    private inline fun share(right: (Int, Int) -> Boolean): Double {
        val n = total
        if (n == 0) return 0.0
        var ok = 0
        for (t in confusion.indices) for (p in confusion.indices) if (right(t, p)) ok += confusion[t][p]
        return ok.toDouble() / n
    }
}

/** The paper's evaluation (a random 70/30 split of windows) and ours (leave one person out). */
public object NaoEvaluation {
    /** Share of windows the paper trained on. */
    public const val TRAIN_FRACTION: Double = 0.7

    /**
     * Trains on a random [trainFraction] of the windows (shuffled with [seed]) and scores the rest. Windows of the
     * same person and even overlapping windows of the same gesture fall on both sides, which flatters the score.
     */
    public fun randomSplit(windows: NaoWindows, params: ForestParams = NaoPreset.FOREST, trainFraction: Double = TRAIN_FRACTION, seed: Long = 1L): NaoScores {
        require(trainFraction > 0.0 && trainFraction < 1.0) { "trainFraction must be in (0, 1), was $trainFraction" }
        require(windows.size >= 2) { "need at least 2 windows, got ${windows.size}" }
        val order = (0 until windows.size).toMutableList()
        val random = SplittableRandom(seed)
        for (i in order.size - 1 downTo 1) {
            val j = random.nextInt(i + 1)
            val t = order[i]; order[i] = order[j]; order[j] = t
        }
        val cut = (windows.size * trainFraction).toInt().coerceIn(1, windows.size - 1)
        val confusion = Array(NaoPreset.LABELS.size) { IntArray(NaoPreset.LABELS.size) }
        score(windows.subset(order.subList(0, cut)), windows.subset(order.subList(cut, order.size)), params, confusion)
        return NaoScores(confusion)
    }

    /** For each person: trains on everyone else's windows and scores theirs; the confusions are summed. */
    public fun leaveOnePersonOut(windows: NaoWindows, params: ForestParams = NaoPreset.FOREST): NaoScores {
        val people = windows.people.distinct()
        require(people.size >= 2) { "leave-one-person-out needs at least 2 people, got ${people.size}" }
        val confusion = Array(NaoPreset.LABELS.size) { IntArray(NaoPreset.LABELS.size) }
        for (person in people) {
            val test = windows.people.indices.filter { windows.people[it] == person }
            val train = windows.people.indices.filter { windows.people[it] != person }
            score(windows.subset(train), windows.subset(test), params, confusion)
        }
        return NaoScores(confusion)
    }

    private fun score(train: NaoWindows, test: NaoWindows, params: ForestParams, confusion: Array<IntArray>) {
        val labels = IntArray(train.size) { NaoPreset.LABELS.indexOf(train.labels[it]) }
        val forest = RandomForest.train(train.features, labels, NaoPreset.LABELS.size, params)
        val probabilities = DoubleArray(NaoPreset.LABELS.size)
        for (i in 0 until test.size) confusion[NaoPreset.LABELS.indexOf(test.labels[i])][forest.predict(test.features[i], probabilities)]++
    }
}
