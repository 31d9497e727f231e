package org.hapticon.gesture.recognition

import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import org.hapticon.core.io.SchemaJson
import java.util.SplittableRandom
import kotlin.math.roundToInt
import kotlin.math.sqrt

/**
 * How a [RandomForest] is grown: [trees] CART trees (Gini impurity), each on a bootstrap sample when [bootstrap]
 * (else on all samples), choosing among [featuresPerSplit] random features at every split (0 = √(feature count),
 * rounded), split while deeper than [maxDepth] is not reached, the node holds at least [minSamplesSplit] samples
 * and both children keep at least [minLeaf] samples. [seed] makes training repeatable. The NAO paper's forest is
 * [org.hapticon.gesture.recognition.NaoPreset.FOREST] (scikit-learn's names: n_estimators, max_depth,
 * max_features, min_samples_split, criterion, bootstrap).
 */
public class ForestParams(
    public val trees: Int = 30,
    public val maxDepth: Int = 16,
    public val minLeaf: Int = 1,
    public val featuresPerSplit: Int = 0,
    public val seed: Long = 1L,
    public val minSamplesSplit: Int = 2,
    public val bootstrap: Boolean = true,
) {
    init {
        require(trees in 1..MAX_TREES) { "trees must be in 1..$MAX_TREES, was $trees" }
        require(maxDepth in 1..64) { "maxDepth must be in 1..64, was $maxDepth" }
        require(minLeaf >= 1) { "minLeaf must be >= 1, was $minLeaf" }
        require(featuresPerSplit >= 0) { "featuresPerSplit must be >= 0 (0 = square root), was $featuresPerSplit" }
        require(minSamplesSplit >= 2) { "minSamplesSplit must be >= 2, was $minSamplesSplit" }
    }

    override fun toString(): String =
        "ForestParams(trees=$trees, maxDepth=$maxDepth, minLeaf=$minLeaf, featuresPerSplit=$featuresPerSplit, seed=$seed, " +
            "minSamplesSplit=$minSamplesSplit, bootstrap=$bootstrap)"

    public companion object {
        /** More trees than this buys nothing but model size. */
        public const val MAX_TREES: Int = 1000
    }
}

/**
 * A random forest classifier over [featureCount] features and [classCount] classes (0 until classCount).
 * Each tree votes for the majority class of the leaf a sample reaches; [predict] gives the vote shares.
 * Built by [train], restored by [fromJson]; immutable and safe to share between threads.
 */
public class RandomForest private constructor(
    public val featureCount: Int,
    public val classCount: Int,
    private val trees: List<Tree>,
) {
    /** Number of trees. */
    public val treeCount: Int get() = trees.size

    /** Total nodes over all trees (a size measure). */
    public val nodeCount: Int get() = trees.sumOf { it.feature.size }

    /**
     * Writes into [probabilities] (size [classCount]) the share of trees voting for each class and returns the
     * class with most votes (the lowest index on a tie). [features] must hold [featureCount] finite values.
     */
    public fun predict(features: DoubleArray, probabilities: DoubleArray): Int {
        require(features.size == featureCount) { "expected $featureCount features, got ${features.size}" }
        require(probabilities.size == classCount) { "expected room for $classCount probabilities, got ${probabilities.size}" }
        probabilities.fill(0.0)
        for (t in trees.indices) probabilities[trees[t].vote(features)] += 1.0 // indexed: no iterator per call
        var best = 0
        for (c in 0 until classCount) {
            probabilities[c] /= trees.size
            if (probabilities[c] > probabilities[best]) best = c
        }
        return best
    }

    /** A forest of only the first [count] trees — what training with `trees = count` and the same seed gives. */
    public fun firstTrees(count: Int): RandomForest {
        require(count in 1..trees.size) { "count must be in 1..${trees.size}, was $count" }
        return RandomForest(featureCount, classCount, trees.subList(0, count))
    }

    /** The forest as JSON: counts and, per tree, parallel node arrays (see [fromJson]). */
    public fun toJson(): JsonObject = SchemaJson.encodeToElement(ForestDocument.serializer(), toDocument()) as JsonObject

    internal fun toDocument(): ForestDocument = ForestDocument(featureCount, classCount, trees.map { TreeDocument(it.feature, it.threshold, it.left, it.right) })

    public companion object {
        /**
         * Grows a forest on rows [features] (all of one length, finite) labelled [labels] (each in 0 until
         * [classCount]). Deterministic for a given [params] seed. [IllegalArgumentException] for empty or
         * ragged input, non-finite features or labels out of range.
         */
        public fun train(features: List<DoubleArray>, labels: IntArray, classCount: Int, params: ForestParams): RandomForest {
            require(features.isNotEmpty()) { "cannot train on no samples" }
            require(features.size == labels.size) { "${features.size} feature rows but ${labels.size} labels" }
            require(classCount >= 1) { "classCount must be >= 1, was $classCount" }
            val width = features[0].size
            require(width >= 1) { "samples need at least one feature" }
            for ((row, values) in features.withIndex()) {
                require(values.size == width) { "row $row has ${values.size} features, expected $width" }
                require(values.all { it.isFinite() }) { "row $row holds a non-finite feature" }
                require(labels[row] in 0 until classCount) { "label ${labels[row]} of row $row is outside 0 until $classCount" }
            }
            val perSplit = if (params.featuresPerSplit == 0) sqrt(width.toDouble()).roundToInt().coerceIn(1, width)
            else params.featuresPerSplit.coerceAtMost(width)
            val random = SplittableRandom(params.seed)
            val grower = TreeGrower(features, labels, classCount, perSplit, params)
            val trees = List(params.trees) { grower.grow(random.split()) }
            return RandomForest(width, classCount, trees)
        }

        /**
         * The forest [json] describes, as written by [toJson]. [IllegalArgumentException] naming the problem
         * when a member is missing or malformed or a node points outside its tree.
         */
        public fun fromJson(json: JsonElement): RandomForest {
            // The forest alone is checked with the paths it has inside a model file ("forest", "forest.trees[3]").
            val checked = SchemaJson.check(json, ForestDocument.serializer().descriptor, "forest", ModelReport())
            return fromDocument(SchemaJson.format.decodeFromJsonElement(ForestDocument.serializer(), checked))
        }

        internal fun fromDocument(doc: ForestDocument): RandomForest {
            require(doc.featureCount >= 1 && doc.classCount >= 1) { "forest: featureCount and classCount must be >= 1" }
            val trees = doc.trees.mapIndexed { i, tree -> Tree.of(tree, doc.featureCount, doc.classCount, "trees[$i]") }
            require(trees.isNotEmpty()) { "forest: no trees" }
            return RandomForest(doc.featureCount, doc.classCount, trees)
        }
    }
}

/**
 * One tree as parallel node arrays. Node 0 is the root. An inner node sends x to [left] when
 * x[feature] ≤ threshold, else to [right]; a leaf has feature −1 and votes for class `left`.
 */
private class Tree(val feature: IntArray, val threshold: DoubleArray, val left: IntArray, val right: IntArray) {
    fun vote(x: DoubleArray): Int {
        var node = 0
        while (true) {
            val f = feature[node]
            if (f < 0) return left[node]
            node = if (x[f] <= threshold[node]) left[node] else right[node]
        }
    }


    companion object {
        fun of(doc: TreeDocument, featureCount: Int, classCount: Int, where: String): Tree {
            val feature = doc.feature
            val threshold = doc.threshold
            val left = doc.left
            val right = doc.right
            val n = feature.size
            require(n >= 1 && threshold.size == n && left.size == n && right.size == n) { "$where: node arrays must be non-empty and equally long" }
            for (i in 0 until n) {
                if (feature[i] < 0) {
                    require(left[i] in 0 until classCount) { "$where: leaf $i votes for class ${left[i]}, outside 0 until $classCount" }
                } else {
                    require(feature[i] < featureCount) { "$where: node $i splits on feature ${feature[i]}, outside 0 until $featureCount" }
                    // Children come after their parent, so a malformed tree cannot loop.
                    require(left[i] in i + 1 until n && right[i] in i + 1 until n) { "$where: node $i has children outside ${i + 1} until $n" }
                }
            }
            return Tree(feature, threshold, left, right)
        }
    }
}

/** CART growth with Gini impurity on bootstrap samples (or all samples); scratch arrays are reused across trees. */
private class TreeGrower(
    private val x: List<DoubleArray>,
    private val y: IntArray,
    private val classCount: Int,
    private val perSplit: Int,
    private val params: ForestParams,
) {
    private val n = x.size
    private val width = x[0].size
    private val sample = IntArray(n)
    private val values = DoubleArray(n)
    private val classes = IntArray(n)
    private val featureOrder = IntArray(width) { it }
    private val leftCounts = IntArray(classCount)
    private val totalCounts = IntArray(classCount)

    private val feature = ArrayList<Int>()
    private val threshold = ArrayList<Double>()
    private val left = ArrayList<Int>()
    private val right = ArrayList<Int>()

    fun grow(random: SplittableRandom): Tree {
        for (i in 0 until n) sample[i] = if (params.bootstrap) random.nextInt(n) else i
        feature.clear(); threshold.clear(); left.clear(); right.clear()
        build(0, n, 0, random)
        return Tree(feature.toIntArray(), threshold.toDoubleArray(), left.toIntArray(), right.toIntArray())
    }

    /** Appends the subtree of `sample[from until to]` in preorder and returns its root's index. */
    private fun build(from: Int, to: Int, depth: Int, random: SplittableRandom): Int {
        val node = feature.size
        feature += -1; threshold += 0.0; left += 0; right += 0
        totalCounts.fill(0)
        for (i in from until to) totalCounts[y[sample[i]]]++
        var majority = 0
        for (c in 0 until classCount) if (totalCounts[c] > totalCounts[majority]) majority = c
        left[node] = majority
        val size = to - from
        if (depth >= params.maxDepth || size < 2 * params.minLeaf || size < params.minSamplesSplit || totalCounts[majority] == size) return node

        var bestScore = parentScore(size)
        var bestFeature = -1
        var bestThreshold = 0.0
        // A partial Fisher–Yates shuffle picks perSplit distinct features.
        for (k in 0 until perSplit) {
            val j = k + random.nextInt(width - k)
            val f = featureOrder[j]
            featureOrder[j] = featureOrder[k]
            featureOrder[k] = f
            for (i in from until to) {
                values[i - from] = x[sample[i]][f]
                classes[i - from] = y[sample[i]]
            }
            sortPairs(values, classes, 0, size - 1)
            leftCounts.fill(0)
            var leftSquares = 0L
            var rightSquares = 0L
            for (c in 0 until classCount) rightSquares += totalCounts[c].toLong() * totalCounts[c]
            for (i in 0 until size - 1) {
                val c = classes[i]
                val before = leftCounts[c]
                leftSquares += 2L * before + 1
                val rightBefore = totalCounts[c] - before
                rightSquares -= 2L * rightBefore - 1
                leftCounts[c] = before + 1
                val leftSize = i + 1
                if (values[i] == values[i + 1] || leftSize < params.minLeaf || size - leftSize < params.minLeaf) continue
                // Maximising Σ count²/size over both sides minimises the size-weighted Gini impurity.
                val score = leftSquares.toDouble() / leftSize + rightSquares.toDouble() / (size - leftSize)
                if (score > bestScore + 1e-12) {
                    bestScore = score
                    bestFeature = f
                    val mid = values[i] + (values[i + 1] - values[i]) * 0.5
                    bestThreshold = if (mid < values[i + 1]) mid else values[i]
                }
            }
        }
        if (bestFeature < 0) return node
        var split = from
        for (i in from until to) {
            if (x[sample[i]][bestFeature] <= bestThreshold) {
                val t = sample[split]; sample[split] = sample[i]; sample[i] = t
                split++
            }
        }
        feature[node] = bestFeature
        threshold[node] = bestThreshold
        val l = build(from, split, depth + 1, random)
        val r = build(split, to, depth + 1, random)
        left[node] = l
        right[node] = r
        return node
    }

    private fun parentScore(size: Int): Double {
        var squares = 0L
        for (c in 0 until classCount) squares += totalCounts[c].toLong() * totalCounts[c]
        return squares.toDouble() / size
    }

    /** Sorts `values[lo..hi]` ascending, moving `classes` along (quicksort, insertion sort for short runs). */
    private fun sortPairs(values: DoubleArray, classes: IntArray, lo: Int, hi: Int) {
        var low = lo
        var high = hi
        while (high - low > 16) {
            val pivot = median3(values[low], values[(low + high) ushr 1], values[high])
            var i = low
            var j = high
            while (i <= j) {
                while (values[i] < pivot) i++
                while (values[j] > pivot) j--
                if (i <= j) {
                    swap(values, classes, i, j)
                    i++; j--
                }
            }
            // Recurse into the shorter side, loop on the longer, so the stack stays logarithmic.
            if (j - low < high - i) {
                sortPairs(values, classes, low, j); low = i
            } else {
                sortPairs(values, classes, i, high); high = j
            }
        }
        for (i in low + 1..high) {
            val v = values[i]
            val c = classes[i]
            var k = i - 1
            while (k >= low && values[k] > v) {
                values[k + 1] = values[k]; classes[k + 1] = classes[k]; k--
            }
            values[k + 1] = v; classes[k + 1] = c
        }
    }

    private fun median3(a: Double, b: Double, c: Double): Double =
        if (a < b) (if (b < c) b else if (a < c) c else a) else (if (a < c) a else if (b < c) c else b)

    private fun swap(values: DoubleArray, classes: IntArray, i: Int, j: Int) {
        val v = values[i]; values[i] = values[j]; values[j] = v
        val c = classes[i]; classes[i] = classes[j]; classes[j] = c
    }
}
