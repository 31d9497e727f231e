package org.hapticon.gesture.social

import kotlin.math.abs

/**
 * A regression stump, `if (x[feature] <= threshold) left else right` (WEKA's `DecisionStump.whichSubset`,
 * `weka/classifiers/trees/DecisionStump.java` lines 735–754, for numeric attributes without missing values).
 */
public class Stump(public val feature: Int, public val threshold: Double, public val left: Double, public val right: Double) {
    /** The stump's value at [x]. */
    public fun at(x: DoubleArray): Double = if (x[feature] <= threshold) left else right
}

/**
 * LogitBoost with decision stumps as WEKA runs it — the EIT-skin paper's classifier ("the 'LogitBoost' classifier [17]
 * with decision stumps as a base (weak) learner", 001_e790093bbd2e3cd3.txt:136; "WEKA was used for classification",
 * :138). Friedman, Hastie & Tibshirani's multiclass LogitBoost (Ann. Statist. 28(2), 2000) in the arithmetic of
 * `weka.classifiers.meta.LogitBoost` with `weka.classifiers.trees.DecisionStump`, weka-stable 3.8.6 (citations are
 * lines of that release's `-sources.jar`):
 *
 * - F = 0 and p_j = 1/J to start (LogitBoost.java line 941);
 * - each round, for each class j: the response z = 1/p (true class) or −1/(1 − p), clipped to ±[Settings.zMax], and
 *   the weight w = (y − p)/z (lines 1124–1145); the weights rescaled to sum to the training set's (lines 1148–1154);
 *   with [Settings.weightThresholdPercent] < 100 only the heaviest instances holding that share of the weight
 *   (`selectWeightQuantile`, lines 342–369, 1157–1160); a `DecisionStump` fitted to z by weighted least squares
 *   (below); with two classes only one stump, the other class getting its negation (lines 1174–1177, 1192–1195);
 * - F_j += (f_j − mean_k f_k)·(J − 1)/J with f_j = [Settings.shrinkage]·stump_j(x) (lines 1181–1201), p = softmax(F)
 *   (`probs`, lines 1227–1242);
 * - stop after [Settings.iterations] rounds, or once a round changes the mean negative log-likelihood by less than
 *   [Settings.likelihoodThreshold] (lines 1005–1025, 1080–1092).
 *
 * The stump (`DecisionStump.buildClassifier` lines 124–206, `findSplitNumericNumeric` lines 641–705, `variance` lines
 * 715–726): for each feature in turn, the instances sorted by it with WEKA's own quicksort ([WekaOrder.quickSort]; the
 * order carries over from one feature to the next, as WEKA sorts its copy in place), every cut midway between two
 * distinct neighbours scored by the weighted sum of squares left and right; the first strictly smallest wins, per
 * feature and across features; the stump predicts each side's weighted mean of z. A feature with no cut scores
 * `Double.MAX_VALUE` and, if it is the first, predicts 0 on both sides, as WEKA's does.
 *
 * Not implemented (the paper names no WEKA option, so its defaults apply): resampling (-Q, which WEKA uses only for a
 * base learner that cannot take weights; DecisionStump can), estimated priors (-use-estimated-priors, off by default)
 * and, from WEKA 3.7, internal cross-validation to choose the number of rounds (-F, 0 = off by default). Tested against
 * WEKA itself (`LogitBoostWekaOracleTest`): the same predictions and, to the last bit, probabilities on the same data
 * and settings.
 *
 * [predict] reuses scratch arrays: one instance per thread.
 *
 * Why our own, with WEKA as the test oracle only: WEKA is GPL-3 and a 12 MB desktop library (Swing, JAXB, netlib);
 * Smile has no LogitBoost; the algorithm is about two hundred lines here.
 */
public class LogitBoost private constructor(
    /** Features per sample. */
    public val featureCount: Int,
    /** Classes, 0 until classCount. */
    public val classCount: Int,
    /** rounds[m][j]: round m's stump for class j, shrinkage included (WEKA multiplies every stump output by it). */
    private val rounds: List<List<Stump>>,
) {
    private val fs = DoubleArray(classCount)
    private val pred = DoubleArray(classCount)

    /** Rounds trained. */
    public val iterations: Int get() = rounds.size

    /**
     * Writes p_j(x) into [probabilities] (size [classCount]) and returns the most probable class, the first on a tie
     * (`LogitBoost.processInstance`, lines 1277–1306; `AbstractClassifier.classifyInstance`, lines 171–192).
     */
    public fun predict(x: DoubleArray, probabilities: DoubleArray): Int {
        require(x.size == featureCount) { "expected $featureCount features, got ${x.size}" }
        require(probabilities.size == classCount) { "expected room for $classCount probabilities" }
        fs.fill(0.0)
        for (round in rounds) addRound(round, x, pred, fs)
        probabilities(fs, probabilities)
        var best = 0
        for (j in 1 until classCount) if (probabilities[j] > probabilities[best]) best = j
        return best
    }

    /** The stumps, round by round, class by class (for [SocialTouchModel]'s JSON). */
    internal fun flatStumps(): List<Stump> = rounds.flatten()

    /**
     * WEKA's LogitBoost options that change its model, with WEKA's defaults (`weka-stable` 3.8.6): `-I` [iterations]
     * 10 (`IteratedSingleClassifierEnhancer.java` line 55), `-H` [shrinkage] 1 (LogitBoost.java line 227), `-Z` [zMax]
     * 3 (line 212; "Friedman suggests between 2 and 4"), `-P` [weightThresholdPercent] 100 (line 209), `-L`
     * [likelihoodThreshold] −Double.MAX_VALUE, i.e. never stop early (line 224). The paper states none of them
     * (paper silent, 001_e790093bbd2e3cd3.txt:136–138): [WEKA_DEFAULTS] is what WEKA runs unless told otherwise.
     */
    public data class Settings(
        val iterations: Int = 10,
        val shrinkage: Double = 1.0,
        val zMax: Double = 3.0,
        val weightThresholdPercent: Int = 100,
        val likelihoodThreshold: Double = -Double.MAX_VALUE,
    ) {
        init {
            require(iterations in 1..10_000) { "iterations must be in 1..10000, was $iterations" }
            require(shrinkage > 0.0 && shrinkage.isFinite()) { "shrinkage must be positive and finite, was $shrinkage" }
            require(zMax > 0.0 && zMax.isFinite()) { "zMax must be positive and finite, was $zMax" }
            require(weightThresholdPercent in 1..100) { "weightThresholdPercent must be in 1..100, was $weightThresholdPercent" }
            require(!likelihoodThreshold.isNaN()) { "likelihoodThreshold must be a number" }
        }
    }

    public companion object {
        /** WEKA's defaults, the paper's settings as far as it says (it names none). */
        public val WEKA_DEFAULTS: Settings = Settings()

        /** WEKA's default number of rounds. */
        public const val DEFAULT_ITERATIONS: Int = 10

        /** A model of [flat] stumps ([classCount] per round), as [flatStumps] lists them. */
        internal fun of(featureCount: Int, classCount: Int, flat: List<Stump>): LogitBoost {
            require(flat.isNotEmpty() && flat.size % classCount == 0) { "need a whole number of rounds of $classCount stumps, got ${flat.size}" }
            require(flat.all { it.feature in 0 until featureCount && it.threshold.isFinite() && it.left.isFinite() && it.right.isFinite() }) { "a stump is out of range" }
            return LogitBoost(featureCount, classCount, flat.chunked(classCount))
        }

        /** [train] with WEKA's defaults but [iterations] rounds. */
        public fun train(features: List<DoubleArray>, labels: IntArray, classCount: Int, iterations: Int): LogitBoost =
            train(features, labels, classCount, WEKA_DEFAULTS.copy(iterations = iterations))

        /**
         * Trains on [features] (rows of equal length, finite) with [labels] in 0 until [classCount] ≥ 2, in the rows'
         * order (WEKA's sums follow the instance order; give the same order to compare with WEKA).
         * @throws IllegalArgumentException for empty, ragged or non-finite input or a bad label.
         */
        public fun train(features: List<DoubleArray>, labels: IntArray, classCount: Int, settings: Settings = WEKA_DEFAULTS): LogitBoost {
            require(features.isNotEmpty()) { "no training samples" }
            require(features.size == labels.size) { "${features.size} rows but ${labels.size} labels" }
            require(classCount >= 2) { "need at least 2 classes, got $classCount" }
            val width = features[0].size
            require(width >= 1) { "need at least one feature" }
            for ((i, row) in features.withIndex()) {
                require(row.size == width) { "row $i has ${row.size} features, row 0 has $width" }
                require(row.all { it.isFinite() }) { "row $i has a non-finite feature" }
                require(labels[i] in 0 until classCount) { "label ${labels[i]} of row $i is outside 0 until $classCount" }
            }
            val n = features.size
            val j2 = classCount
            val trainFs = Array(n) { DoubleArray(j2) }
            val probs = Array(n) { DoubleArray(j2) { 1.0 / j2 } }
            // Every instance weighs 1, so the sum of weights is n, added up as WEKA does.
            var origSum = 0.0
            repeat(n) { origSum += 1.0 }
            val z = DoubleArray(n)
            val w = DoubleArray(n)
            val all = IntArray(n) { it }
            val pred = DoubleArray(j2)
            val rounds = ArrayList<List<Stump>>(settings.iterations)
            var logLikelihood = negativeLogLikelihood(labels, probs, origSum)
            for (m in 0 until settings.iterations) {
                val previous = logLikelihood
                val round = ArrayList<Stump>(j2)
                for (j in 0 until j2) {
                    for (i in 0 until n) {
                        val p = probs[i][j]
                        val actual = if (labels[i] == j) 1.0 else 0.0
                        var zi: Double
                        if (actual == 1.0) {
                            zi = 1.0 / p
                            if (zi > settings.zMax) zi = settings.zMax
                        } else {
                            zi = -1.0 / (1.0 - p)
                            if (zi < -settings.zMax) zi = -settings.zMax
                        }
                        z[i] = zi
                        w[i] = 1.0 * ((actual - p) / zi)
                    }
                    var sumOfWeights = 0.0
                    for (i in 0 until n) sumOfWeights += w[i]
                    val scalingFactor = origSum / sumOfWeights
                    for (i in 0 until n) w[i] = w[i] * scalingFactor
                    val subset = if (settings.weightThresholdPercent < 100) selectWeightQuantile(w, settings.weightThresholdPercent.toDouble() / 100) else all
                    val stump = fitStump(features, subset, z, w, width)
                    round += Stump(stump.feature, stump.threshold, settings.shrinkage * stump.left, settings.shrinkage * stump.right)
                    if (j2 == 2) {
                        round += Stump(stump.feature, stump.threshold, -round[0].left, -round[0].right)
                        break
                    }
                }
                for (i in 0 until n) {
                    addRound(round, features[i], pred, trainFs[i])
                    probabilities(trainFs[i], probs[i])
                }
                rounds += round
                logLikelihood = negativeLogLikelihood(labels, probs, origSum)
                if (abs(previous - logLikelihood) < settings.likelihoodThreshold) break
            }
            return LogitBoost(width, j2, rounds)
        }

        /** F += one round, centred (LogitBoost.java lines 1183–1201): with two classes the second is the first's negation. */
        private fun addRound(round: List<Stump>, x: DoubleArray, pred: DoubleArray, fs: DoubleArray) {
            val classes = fs.size
            var predSum = 0.0
            for (j in 0 until classes) {
                pred[j] = round[j].at(x)
                if (classes == 2) {
                    pred[1] = -pred[0]
                    break
                }
                predSum += pred[j]
            }
            predSum /= classes
            for (j in 0 until classes) fs[j] += (pred[j] - predSum) * (classes - 1) / classes
        }

        /** `LogitBoost.probs` (lines 1227–1242): softmax after subtracting the largest F. */
        private fun probabilities(fs: DoubleArray, into: DoubleArray) {
            var maxF = -Double.MAX_VALUE
            for (f in fs) if (f > maxF) maxF = f
            var sum = 0.0
            for (j in fs.indices) {
                into[j] = Math.exp(fs[j] - maxF)
                sum += into[j]
            }
            for (j in fs.indices) into[j] /= sum
        }

        /** `negativeLogLikelihood` (lines 1080–1092), every weight 1. */
        private fun negativeLogLikelihood(labels: IntArray, probs: Array<DoubleArray>, sumOfWeights: Double): Double {
            var ll = 0.0
            for (i in labels.indices) ll -= 1.0 * Math.log(probs[i][labels[i]])
            return ll / sumOfWeights
        }

        /** `selectWeightQuantile` (lines 342–369): the heaviest instances, heaviest first, until [quantile] of the weight is in. */
        private fun selectWeightQuantile(w: DoubleArray, quantile: Double): IntArray {
            var sumOfWeights = 0.0
            for (v in w) sumOfWeights += v
            val mass = sumOfWeights * quantile
            val sorted = WekaOrder.sortedPositions(w.copyOf())
            val out = ArrayList<Int>()
            sumOfWeights = 0.0
            for (i in w.size - 1 downTo 0) {
                out += sorted[i]
                sumOfWeights += w[sorted[i]]
                if (sumOfWeights > mass && i > 0 && w[sorted[i]] != w[sorted[i - 1]]) break
            }
            return out.toIntArray()
        }

        /** WEKA's `DecisionStump` on a numeric class (the response [z]) with weights [w], over the instances [subset] in that order. */
        private fun fitStump(x: List<DoubleArray>, subset: IntArray, z: DoubleArray, w: DoubleArray, width: Int): Stump {
            var order = subset.copyOf()
            val values = DoubleArray(order.size)
            var bestVal = Double.MAX_VALUE
            var bestAtt = -1
            var bestPoint = -Double.MAX_VALUE
            var bestLeft = 0.0
            var bestRight = 0.0
            // DecisionStump.m_SplitPoint: a field, so a feature without a cut leaves the previous feature's cut in it.
            var splitPoint = 0.0
            var first = true
            for (att in 0 until width) {
                var attBest = Double.MAX_VALUE
                var left = 0.0
                var right = 0.0
                var s0 = 0.0; var ss0 = 0.0; var w0 = 0.0
                var s1 = 0.0; var ss1 = 0.0; var w1 = 0.0
                var totalSum = 0.0
                var totalW = 0.0
                for (i in order) {
                    s1 += z[i] * w[i]
                    ss1 += z[i] * z[i] * w[i]
                    w1 += w[i]
                    totalW += w[i]
                    totalSum += z[i] * w[i]
                }
                if (totalW <= 0) {
                    // findSplitNumericNumeric returns before choosing: the stump keeps the running sums (lines 667–670).
                    right = s1
                } else {
                    for (k in order.indices) values[k] = x[order[k]][att]
                    val positions = WekaOrder.sortedPositions(values)
                    order = IntArray(order.size) { order[positions[it]] }
                    for (k in 0 until order.size - 1) {
                        val i = order[k]
                        val here = x[i][att]
                        val next = x[order[k + 1]][att]
                        s0 += z[i] * w[i]; ss0 += z[i] * z[i] * w[i]; w0 += w[i]
                        s1 -= z[i] * w[i]; ss1 -= z[i] * z[i] * w[i]; w1 -= w[i]
                        if (here < next) {
                            val cut = (here + next) / 2.0
                            var variance = 0.0
                            if (w0 > 0) variance += ss0 - ((s0 * s0) / w0)
                            if (w1 > 0) variance += ss1 - ((s1 * s1) / w1)
                            if (variance < attBest) {
                                splitPoint = cut
                                attBest = variance
                                left = if (w0 > 0) s0 / w0 else totalSum / totalW
                                right = if (w1 > 0) s1 / w1 else totalSum / totalW
                            }
                        }
                    }
                }
                if (first || attBest < bestVal) {
                    bestVal = attBest
                    bestAtt = att
                    bestPoint = splitPoint
                    bestLeft = left
                    bestRight = right
                }
                first = false
            }
            return Stump(bestAtt, bestPoint, bestLeft, bestRight)
        }
    }
}
