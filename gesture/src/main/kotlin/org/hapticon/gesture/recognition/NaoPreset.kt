package org.hapticon.gesture.recognition

import java.util.SplittableRandom

/**
 * The touch-gesture pipeline of the NAO fabric-sensor paper (Burns, Lee, Seifi, Faulkner & Kuchenbecker, Front.
 * Robot. AI 9:840335, 2022; its text is 004_7d5078645d142b2a.txt in the papers' index), as a named preset beside our
 * default ([WindowConfig] defaults, [WindowFeatures]' 33 features, [ForestParams] defaults, [GestureLabel]'s labels):
 *
 * - **Input:** four fabric resistance sensors on the NAO's left arm, [LOCATIONS] hand, lower arm, upper arm and
 *   shoulder (004_7d5078645d142b2a.txt:5, :105), sampled at [SAMPLE_RATE] = 40 Hz (:156).
 * - **Windows:** w = [WINDOW_FRAMES] = 80 samples, "about 2 s" (:170), successive windows overlapping by 0.5w
 *   ([HOP_FRAMES] = 40, :168); a window takes a gesture's label when it overlaps that gesture by at least
 *   [LABEL_OVERLAP]·w = 60 samples, else `none` (:168, [windowLabel]). (Our default labels by "half the window or
 *   half the gesture" and leaves the rest out; see [LabelledRecording.windowLabel].)
 * - **Features:** 31 per sensor, 124 in all ([FEATURE_INDICES], :168): the entropy of the signal, and the sum, max,
 *   min, average, median, standard deviation, variance, area under the curve, interquartile range and number of
 *   peaks of the signal, its first and its second derivative (1 + 3 × 10 = 31). Our 33 add the entropy of both
 *   derivatives.
 * - **Classifiers:** a scikit-learn random forest (:168) per task ([NaoTask]: location, intensity, gesture, and
 *   gesture with intensity together, :174, :205-209), each with its own [ForestParams] in [FORESTS].
 * - **Evaluation:** a 70 %–30 % train-test split "randomly sampled across all participant data" (:170,
 *   [NaoEvaluation.randomSplit]); ours adds leave-one-person-out.
 *
 * Its own label strings are used rather than [GestureLabel] (whose gestures are the messenger's stroke, hit, knock
 * and hug): the NAO classes are a research preset evaluated offline ([NaoEvaluation]), not icons to send.
 */
public object NaoPreset {
    /** Samples per second of the fabric sensors: 40 Hz (004_7d5078645d142b2a.txt:156). */
    public const val SAMPLE_RATE: Double = 40.0

    /** Resistive channels, one per [LOCATIONS] entry, in that order. */
    public const val CHANNELS: Int = 4

    /** Samples per window: w = 80, about 2 s (004_7d5078645d142b2a.txt:170). */
    public const val WINDOW_FRAMES: Int = 80

    /** Samples between window starts: an overlap of 0.5w between successive windows (004_7d5078645d142b2a.txt:168). */
    public const val HOP_FRAMES: Int = 40

    /** Share of the window a gesture must cover for the window to take its label: 0.75w (004_7d5078645d142b2a.txt:168). */
    public const val LABEL_OVERLAP: Double = 0.75

    /** The label of windows that no gesture covers enough: "none" (004_7d5078645d142b2a.txt:166, :168). */
    public const val NONE: String = "none"

    /** The five gestures: hitting, poking, squeezing, stroking and tickling (004_7d5078645d142b2a.txt:5, :149). */
    public val GESTURES: List<String> = listOf("hit", "poke", "squeeze", "stroke", "tickle")

    /** The two force intensities, gentle and energetic (004_7d5078645d142b2a.txt:5). */
    public val INTENSITIES: List<String> = listOf("gentle", "energetic")

    /** The four sensor locations, the order of the channels: hand, lower arm, upper arm, shoulder (004_7d5078645d142b2a.txt:5, :105). */
    public val LOCATIONS: List<String> = listOf("hand", "lower-arm", "upper-arm", "shoulder")

    /** The 11 combined classes: `gesture-intensity` in [GESTURES] × [INTENSITIES] order, then [NONE] (1/11 = 9 % chance, 004_7d5078645d142b2a.txt:215). */
    public val LABELS: List<String> = GESTURES.flatMap { g -> INTENSITIES.map { "$g-$it" } } + NONE

    /**
     * Which of [WindowFeatures]' 33 per-channel features the paper uses, in our order: all but `d1.entropy` and
     * `d2.entropy`, since the paper takes the entropy of the signal only and the other ten metrics of the signal and
     * both derivatives (004_7d5078645d142b2a.txt:168).
     */
    public val FEATURE_INDICES: IntArray = run {
        val n = WindowFeatures.STATISTICS.size
        val entropy = WindowFeatures.STATISTICS.indexOf("entropy")
        (0 until 3 * n).filter { it < n || it % n != entropy }.toIntArray()
    }

    /** Features per channel: 31 (004_7d5078645d142b2a.txt:168). */
    public val FEATURES_PER_CHANNEL: Int = FEATURE_INDICES.size

    /**
     * The paper's forest for gesture and intensity together, the 11-class classifier of its 74.1 % (Table 2,
     * 004_7d5078645d142b2a.txt:176-199): n_estimators 100 (:194), max_depth 32 (:183), max_features 20 (:184),
     * min_samples_split 8 (:189), min_samples_leaf 1 (:188), criterion "gini" (:179), bootstrap True (:177);
     * class_weight None, max_leaf_nodes None and min_impurity_decrease 0.0 are what [RandomForest] does anyway.
     * random_state None (:197): the paper's forests were not seeded; ours are ([ForestParams.seed]) so a run repeats.
     */
    public val FOREST: ForestParams = forest(trees = 100, maxDepth = 32)

    /**
     * One forest per task, Table 2's values (004_7d5078645d142b2a.txt:174: "the same value was used ... unless
     * otherwise specified"): location 50 trees of depth 40 (:180, :191), intensity 100 of depth 20 (:181, :192),
     * gesture 100 of depth 40 (:182, :193), gesture and intensity [FOREST] (:183, :194).
     */
    public val FORESTS: Map<NaoTask, ForestParams> = mapOf(
        NaoTask.LOCATION to forest(trees = 50, maxDepth = 40),
        NaoTask.INTENSITY to forest(trees = 100, maxDepth = 20),
        NaoTask.GESTURE to forest(trees = 100, maxDepth = 40),
        NaoTask.COMBINED to FOREST,
    )

    private fun forest(trees: Int, maxDepth: Int) =
        ForestParams(trees = trees, maxDepth = maxDepth, featuresPerSplit = 20, minSamplesSplit = 8, minLeaf = 1, bootstrap = true)

    /** The feature names of [channels], in row order, e.g. `r1.entropy`, `r1.d1.iqr`. */
    public fun featureNames(channels: List<String>): List<String> {
        val all = WindowFeatures.names(listOf("x"))
        return channels.flatMap { c -> FEATURE_INDICES.map { "$c${all[it].removePrefix("x")}" } }
    }

    /**
     * The span the window `[from, from + frames)` takes its labels from: one it overlaps by at least
     * ⌈[LABEL_OVERLAP] × frames⌉ samples (the larger overlap wins), else null (the window is [NONE] for every task).
     */
    public fun windowSpan(spans: List<NaoSpan>, from: Int, frames: Int = WINDOW_FRAMES): NaoSpan? {
        val needed = Math.ceil(LABEL_OVERLAP * frames - 1e-9).toInt()
        var best: NaoSpan? = null
        var bestOverlap = 0
        for (span in spans) {
            val overlap = minOf(from + frames, span.to) - maxOf(from, span.from)
            if (overlap >= needed && overlap > bestOverlap) {
                best = span
                bestOverlap = overlap
            }
        }
        return best
    }

    /** The combined label of the window `[from, from + frames)` ([windowSpan]'s, or [NONE]). */
    public fun windowLabel(spans: List<NaoSpan>, from: Int, frames: Int = WINDOW_FRAMES): String = windowSpan(spans, from, frames)?.label ?: NONE

    /** Every window (hop [HOP_FRAMES]) of every recording, with the paper's features and each task's label. */
    public fun windows(recordings: List<NaoRecording>): NaoWindows {
        val extractor = NaoFeatures()
        val features = ArrayList<DoubleArray>()
        val spans = ArrayList<NaoSpan?>()
        val people = ArrayList<String>()
        for (r in recordings) {
            var from = 0
            while (from + WINDOW_FRAMES <= r.frameCount) {
                val row = DoubleArray(CHANNELS * FEATURES_PER_CHANNEL)
                extractor.extract(r.channels, from, row)
                features += row
                spans += windowSpan(r.spans, from)
                people += r.person
                from += HOP_FRAMES
            }
        }
        return NaoWindows(features, spans, people)
    }
}

/**
 * The four things the paper classifies, each with its own forest and its classes including [NaoPreset.NONE]
 * (004_7d5078645d142b2a.txt:174, :205-215): [LOCATION] (chance 1/5), [INTENSITY] (1/3), [GESTURE] (1/6) and
 * [COMBINED] gesture with intensity (1/11).
 */
public enum class NaoTask(public val classes: List<String>) {
    /** Which sensor was touched: hand, lower arm, upper arm, shoulder or none (004_7d5078645d142b2a.txt:205). */
    LOCATION(NaoPreset.LOCATIONS + NaoPreset.NONE),

    /** Gentle, energetic or none (004_7d5078645d142b2a.txt:205). */
    INTENSITY(NaoPreset.INTENSITIES + NaoPreset.NONE),

    /** The gesture without its intensity, or none (004_7d5078645d142b2a.txt:205). */
    GESTURE(NaoPreset.GESTURES + NaoPreset.NONE),

    /** Gesture and intensity together, or none: the 11 [NaoPreset.LABELS] (004_7d5078645d142b2a.txt:209-215). */
    COMBINED(NaoPreset.LABELS),
    ;

    /** This task's label for a window that takes its labels from [span] (null: no gesture, [NaoPreset.NONE]). */
    public fun labelOf(span: NaoSpan?): String = when {
        span == null -> NaoPreset.NONE
        this == LOCATION -> span.location
        this == INTENSITY -> span.intensity
        this == GESTURE -> span.gesture
        else -> span.label
    }

    /** The chance of guessing right among [classes]: 1/size. */
    public val chance: Double get() = 1.0 / classes.size

    /** The lower-case name, as printed. */
    public val label: String get() = name.lowercase()
}

/**
 * Samples `[from, to)` of a recording show gesture [label] (one of [NaoPreset.LABELS] but [NaoPreset.NONE],
 * `gesture-intensity`) performed on the sensor at [location] (one of [NaoPreset.LOCATIONS]).
 */
public class NaoSpan(public val from: Int, public val to: Int, public val label: String, public val location: String) {
    init {
        require(from in 0 until to) { "span [$from, $to) must be non-empty and start at >= 0" }
        require(label in NaoPreset.LABELS && label != NaoPreset.NONE) { "unknown NAO gesture '$label'; expected one of ${NaoPreset.LABELS.dropLast(1)}" }
        require(location in NaoPreset.LOCATIONS) { "unknown NAO sensor location '$location'; expected one of ${NaoPreset.LOCATIONS}" }
    }

    /** The gesture part of [label]: `hit` … `tickle`. */
    public val gesture: String get() = label.substringBefore('-')

    /** The intensity part of [label]: `gentle` or `energetic`. */
    public val intensity: String get() = label.substringAfter('-')

    override fun toString(): String = "$label@$location[$from, $to)"
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

/** Feature rows, the span each takes its labels from (null: none) and whose they are (index-aligned). */
public class NaoWindows(public val features: List<DoubleArray>, public val spans: List<NaoSpan?>, public val people: List<String>) {
    init {
        require(features.size == spans.size && spans.size == people.size) { "${features.size} rows, ${spans.size} spans, ${people.size} people" }
    }

    /** Number of windows. */
    public val size: Int get() = spans.size

    /** [task]'s label of every window. */
    public fun labels(task: NaoTask): List<String> = spans.map { task.labelOf(it) }

    /** The windows at [indices]. */
    public fun subset(indices: List<Int>): NaoWindows = NaoWindows(indices.map { features[it] }, indices.map { spans[it] }, indices.map { people[it] })
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
 * One task's classifier scored on windows: its [confusion] matrix (rows = truth, columns = prediction, both in
 * [NaoTask.classes] order) and the true location of each scored window's gesture ([locations], null for none), so
 * gesture accuracy can be read per sensor as the paper does (004_7d5078645d142b2a.txt:205).
 *
 * - [accuracy]: the share of windows whose label is right;
 * - [averageLabelAccuracy]: the mean over the classes of each class's recall, the diagonal of the row-normalised
 *   confusion matrix. The paper reports "average accuracy" (:205) and "average label accuracy" (:209) without a
 *   formula; a confusion matrix normalised per row (its Figures 4 and 5) read along its diagonal and averaged is
 *   our reading of it, so both are printed.
 */
public class NaoScores(public val task: NaoTask, public val confusion: Array<IntArray>, private val perLocation: Map<String, IntArray> = emptyMap()) {
    init {
        val n = task.classes.size
        require(confusion.size == n && confusion.all { it.size == n }) { "need a $n × $n matrix for ${task.label}" }
    }

    /** Windows scored. */
    public val total: Int get() = confusion.sumOf { it.sum() }

    /** Share of windows whose label is right. */
    public val accuracy: Double get() {
        val n = total
        return if (n == 0) 0.0 else task.classes.indices.sumOf { confusion[it][it] }.toDouble() / n
    }

    /** Mean over the classes with any window of their recall. */
    public val averageLabelAccuracy: Double get() {
        val recalls = task.classes.indices.filter { confusion[it].sum() > 0 }.map { confusion[it][it].toDouble() / confusion[it].sum() }
        return if (recalls.isEmpty()) 0.0 else recalls.average()
    }

    /** Share of [truth]'s windows predicted as [predicted] (the recall when they are equal). */
    public fun share(truth: String, predicted: String): Double {
        val t = task.classes.indexOf(truth)
        val p = task.classes.indexOf(predicted)
        require(t >= 0 && p >= 0) { "unknown ${task.label} label $truth or $predicted; expected one of ${task.classes}" }
        val row = confusion[t].sum()
        return if (row == 0) 0.0 else confusion[t][p].toDouble() / row
    }

    /** Among windows of a gesture performed at [location], the share labelled right; NaN when there are none. */
    public fun accuracyAt(location: String): Double {
        val counts = perLocation[location] ?: return Double.NaN
        return if (counts[1] == 0) Double.NaN else counts[0].toDouble() / counts[1]
    }
}

/** The paper's evaluation (a random 70/30 split of windows) and ours (leave one person out), one forest per task. */
public object NaoEvaluation {
    /** Share of windows the paper trained on: 70 % (004_7d5078645d142b2a.txt:170). */
    public const val TRAIN_FRACTION: Double = 0.7

    /**
     * Trains [task]'s forest on a random [trainFraction] of the windows (shuffled with [seed]) and scores the rest.
     * Windows of the same person and even overlapping windows of the same gesture fall on both sides, which flatters
     * the score.
     */
    public fun randomSplit(windows: NaoWindows, task: NaoTask, params: ForestParams = NaoPreset.FORESTS.getValue(task), trainFraction: Double = TRAIN_FRACTION, seed: Long = 1L): NaoScores {
        require(trainFraction > 0.0 && trainFraction < 1.0) { "trainFraction must be in (0, 1), was $trainFraction" }
        require(windows.size >= 2) { "need at least 2 windows, got ${windows.size}" }
        val order = (0 until windows.size).toMutableList()
        val random = SplittableRandom(seed)
        for (i in order.size - 1 downTo 1) {
            val j = random.nextInt(i + 1)
            val t = order[i]; order[i] = order[j]; order[j] = t
        }
        val cut = (windows.size * trainFraction).toInt().coerceIn(1, windows.size - 1)
        val scoring = Scoring(task)
        scoring.add(windows.subset(order.subList(0, cut)), windows.subset(order.subList(cut, order.size)), params)
        return scoring.scores()
    }

    /** For each person: trains [task]'s forest on everyone else's windows and scores theirs; the confusions are summed. */
    public fun leaveOnePersonOut(windows: NaoWindows, task: NaoTask, params: ForestParams = NaoPreset.FORESTS.getValue(task)): NaoScores {
        val people = windows.people.distinct()
        require(people.size >= 2) { "leave-one-person-out needs at least 2 people, got ${people.size}" }
        val scoring = Scoring(task)
        for (person in people) {
            val test = windows.people.indices.filter { windows.people[it] == person }
            val train = windows.people.indices.filter { windows.people[it] != person }
            scoring.add(windows.subset(train), windows.subset(test), params)
        }
        return scoring.scores()
    }

    /** Sums confusions (and per-location right/total counts of gesture windows) over train/test rounds. */
    private class Scoring(val task: NaoTask) {
        val confusion = Array(task.classes.size) { IntArray(task.classes.size) }
        val perLocation = NaoPreset.LOCATIONS.associateWith { IntArray(2) }

        fun add(train: NaoWindows, test: NaoWindows, params: ForestParams) {
            val trainLabels = train.labels(task)
            val labels = IntArray(train.size) { task.classes.indexOf(trainLabels[it]) }
            val forest = RandomForest.train(train.features, labels, task.classes.size, params)
            val probabilities = DoubleArray(task.classes.size)
            val testLabels = test.labels(task)
            for (i in 0 until test.size) {
                val truth = task.classes.indexOf(testLabels[i])
                val predicted = forest.predict(test.features[i], probabilities)
                confusion[truth][predicted]++
                val span = test.spans[i] ?: continue
                val counts = perLocation.getValue(span.location)
                if (predicted == truth) counts[0]++
                counts[1]++
            }
        }

        fun scores() = NaoScores(task, confusion, perLocation)
    }
}
