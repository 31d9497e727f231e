package org.hapticon.gesture.social

import kotlin.math.exp

/**
 * A regression stump: `if (x[feature] <= threshold) left else right`. A stump with [feature] −1 returns [left]
 * everywhere (the weighted mean, when no split helps).
 */
public class Stump(public val feature: Int, public val threshold: Double, public val left: Double, public val right: Double) {
    /** The stump's value at [x]. */
    public fun at(x: DoubleArray): Double = if (feature < 0 || x[feature] <= threshold) left else right
}

/**
 * Multiclass LogitBoost over regression stumps (Friedman, Hastie & Tibshirani, "Additive logistic regression",
 * Ann. Statist. 2000, Algorithm 6), the classifier of the EIT-skin social-touch paper (which used Weka's
 * `LogitBoost` with its default base learner, `DecisionStump`).
 *
 * With J classes, F_j(x) = 0 and p_j = 1/J to start; each of [iterations] rounds, for every class j, fits a stump
 * f_j by weighted least squares to the working response z = (y*_j − p_j)/(p_j(1 − p_j)) with weights
 * w = p_j(1 − p_j) (z clipped to ±[Z_MAX], weights floored at [MIN_WEIGHT], as Friedman et al. and Weka do), then
 * centres the fits, f_j ← (J − 1)/J·(f_j − mean_k f_k), adds them to F and sets p_j = e^{F_j}/Σ_k e^{F_k}.
 *
 * [predict] reuses a scratch array: one instance per thread.
 *
 * Why our own: Weka is GPL-3 and desktop-bound (Swing, reflection-heavy), Smile has no LogitBoost, and the
 * algorithm with stumps is about a hundred lines that we test directly (a separable and a non-separable set).
 */
public class LogitBoost private constructor(
    /** Features per sample. */
    public val featureCount: Int,
    /** Classes, 0 until classCount. */
    public val classCount: Int,
    /** stumps[m][j]: round m's raw stump for class j (centred across classes when applied). */
    private val stumps: List<List<Stump>>,
) {
    private val raw = DoubleArray(classCount)

    /** Rounds trained. */
    public val iterations: Int get() = stumps.size

    /** Writes p_j(x) into [probabilities] (size [classCount]) and returns the most probable class (lowest on a tie). */
    public fun predict(x: DoubleArray, probabilities: DoubleArray): Int {
        require(x.size == featureCount) { "expected $featureCount features, got ${x.size}" }
        require(probabilities.size == classCount) { "expected room for $classCount probabilities" }
        probabilities.fill(0.0)
        for (round in stumps) addCentred(round, x, raw, probabilities, classCount)
        softmax(probabilities)
        var best = 0
        for (j in 1 until classCount) if (probabilities[j] > probabilities[best]) best = j
        return best
    }

    /** The stumps, round by round, class by class (for [SocialTouchModel]'s JSON). */
    internal fun flatStumps(): List<Stump> = stumps.flatten()

    public companion object {
        /** A model of [flat] stumps ([classCount] per round), as [flatStumps] lists them. */
        internal fun of(featureCount: Int, classCount: Int, flat: List<Stump>): LogitBoost {
            require(flat.isNotEmpty() && flat.size % classCount == 0) { "need a whole number of rounds of $classCount stumps, got ${flat.size}" }
            require(flat.all { it.feature in -1 until featureCount && it.threshold.isFinite() && it.left.isFinite() && it.right.isFinite() }) { "a stump is out of range" }
            return LogitBoost(featureCount, classCount, flat.chunked(classCount))
        }

        /** Working responses are clipped to ±4 (Friedman et al. recommend 2..4; Weka uses 3 — see docs). */
        public const val Z_MAX: Double = 4.0

        /** Smallest working weight, so a nearly certain sample cannot divide by zero. */
        public const val MIN_WEIGHT: Double = 1e-24

        /** Weka's default number of rounds. */
        public const val DEFAULT_ITERATIONS: Int = 10

        /**
         * Trains on [features] (rows of equal length, finite) with [labels] in 0 until [classCount] ≥ 2.
         * @throws IllegalArgumentException for empty, ragged or non-finite input or a bad label.
         */
        public fun train(features: List<DoubleArray>, labels: IntArray, classCount: Int, iterations: Int = DEFAULT_ITERATIONS): LogitBoost {
            require(features.isNotEmpty()) { "no training samples" }
            require(features.size == labels.size) { "${features.size} rows but ${labels.size} labels" }
            require(classCount >= 2) { "need at least 2 classes, got $classCount" }
            require(iterations in 1..10_000) { "iterations must be in 1..10000, was $iterations" }
            val width = features[0].size
            for ((i, row) in features.withIndex()) {
                require(row.size == width) { "row $i has ${row.size} features, row 0 has $width" }
                require(row.all { it.isFinite() }) { "row $i has a non-finite feature" }
                require(labels[i] in 0 until classCount) { "label ${labels[i]} of row $i is outside 0 until $classCount" }
            }
            val n = features.size
            val f = Array(n) { DoubleArray(classCount) }
            val p = Array(n) { DoubleArray(classCount) { 1.0 / classCount } }
            val z = DoubleArray(n)
            val w = DoubleArray(n)
            // Each feature's sample order, computed once: every stump fit is then a linear scan.
            val order = Array(width) { c -> (0 until n).sortedBy { features[it][c] }.toIntArray() }
            val rounds = ArrayList<List<Stump>>(iterations)
            val fitted = DoubleArray(classCount)
            repeat(iterations) {
                val round = List(classCount) { j ->
                    for (i in 0 until n) {
                        val pij = p[i][j]
                        val y = if (labels[i] == j) 1.0 else 0.0
                        w[i] = maxOf(pij * (1 - pij), MIN_WEIGHT)
                        z[i] = ((y - pij) / w[i]).coerceIn(-Z_MAX, Z_MAX)
                    }
                    fitStump(features, order, z, w)
                }
                for (i in 0 until n) {
                    addCentred(round, features[i], fitted, f[i], classCount)
                    System.arraycopy(f[i], 0, p[i], 0, classCount)
                    softmax(p[i])
                }
                rounds += round
            }
            return LogitBoost(width, classCount, rounds)
        }

        /** Weighted least-squares stump of [z] on one feature, the best over all features and thresholds. */
        private fun fitStump(x: List<DoubleArray>, order: Array<IntArray>, z: DoubleArray, w: DoubleArray): Stump {
            var totalW = 0.0
            var totalWz = 0.0
            for (i in z.indices) { totalW += w[i]; totalWz += w[i] * z[i] }
            val mean = totalWz / totalW
            // Maximising (Σ_L wz)²/Σ_L w + (Σ_R wz)²/Σ_R w minimises the weighted squared error.
            var bestGain = totalWz * totalWz / totalW + 1e-12 * totalW
            var best = Stump(-1, 0.0, mean, mean)
            for (c in order.indices) {
                val sorted = order[c]
                var leftW = 0.0
                var leftWz = 0.0
                for (k in 0 until sorted.size - 1) {
                    val i = sorted[k]
                    leftW += w[i]
                    leftWz += w[i] * z[i]
                    val here = x[i][c]
                    val next = x[sorted[k + 1]][c]
                    if (here == next) continue
                    val rightW = totalW - leftW
                    val rightWz = totalWz - leftWz
                    val gain = leftWz * leftWz / leftW + rightWz * rightWz / rightW
                    if (gain > bestGain) {
                        bestGain = gain
                        val mid = here + (next - here) * 0.5
                        best = Stump(c, if (mid < next) mid else here, leftWz / leftW, rightWz / rightW)
                    }
                }
            }
            return best
        }

        /** F_j += (J − 1)/J·(f_j(x) − mean_k f_k(x)) for one round's stumps; [scratch] holds the raw f_j. */
        private fun addCentred(round: List<Stump>, x: DoubleArray, scratch: DoubleArray, into: DoubleArray, classCount: Int) {
            var sum = 0.0
            for (j in 0 until classCount) { scratch[j] = round[j].at(x); sum += scratch[j] }
            val scale = (classCount - 1).toDouble() / classCount
            for (j in 0 until classCount) into[j] += scale * (scratch[j] - sum / classCount)
        }

        internal fun softmax(values: DoubleArray) {
            val max = values.max()
            var sum = 0.0
            for (j in values.indices) { values[j] = exp(values[j] - max); sum += values[j] }
            for (j in values.indices) values[j] /= sum
        }
    }
}
