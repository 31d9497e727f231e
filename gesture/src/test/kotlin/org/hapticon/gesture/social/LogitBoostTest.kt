package org.hapticon.gesture.social

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class LogitBoostTest {
    @Test
    fun train_separableThreeClasses_classifiesEveryPointAndUnseenOnes() {
        // Class = which third of [0, 30) feature 0 falls in; feature 1 is noise.
        val rows = (0 until 90).map { doubleArrayOf(it / 3.0, (it * 37 % 11).toDouble()) }
        val labels = IntArray(rows.size) { (rows[it][0] / 10).toInt() }
        val model = LogitBoost.train(rows, labels, 3, iterations = 20)
        val p = DoubleArray(3)
        assertEquals(labels.toList(), rows.map { model.predict(it, p) })
        assertEquals(listOf(0, 1, 2), listOf(2.0, 15.0, 28.0).map { model.predict(doubleArrayOf(it, 5.0), p) })
        model.predict(doubleArrayOf(28.0, 5.0), p)
        assertEquals(1.0, p.sum(), 1e-12)
        assertEquals(20, model.iterations)
    }

    @Test
    fun train_identicalRows_noStumpCanSplit_soEveryClassStaysEquallyLikely() {
        // 30 × class 0 and 10 × class 1 with the same features. WEKA's DecisionStump finds no cut and predicts 0 on
        // both sides, so LogitBoost never moves off p = 1/J (it does not learn the class frequencies): the first class wins.
        val rows = List(40) { doubleArrayOf(1.0, 2.0) }
        val labels = IntArray(40) { if (it < 30) 1 else 0 }
        val model = LogitBoost.train(rows, labels, 2, iterations = 50)
        val p = DoubleArray(2)
        assertEquals(0, model.predict(doubleArrayOf(1.0, 2.0), p))
        assertEquals(0.5, p[0], 0.0)
        assertEquals(0.5, p[1], 0.0)
    }

    @Test
    fun train_oneRound_isTheWeightedMeanResponseEitherSideOfTheBestCut() {
        // Two classes at x 0, 0 | 1, 1. Round 1: p = 0.5, so z = ±2 and w = 0.25 each, rescaled to sum 4 → 1 each.
        // The cut at 0.5 gives left mean z = +2 (class 0), right −2; F_0 += 2·(2 − 1)/2 = 1 left, −1 right.
        val model = LogitBoost.train(listOf(doubleArrayOf(0.0), doubleArrayOf(0.0), doubleArrayOf(1.0), doubleArrayOf(1.0)), intArrayOf(0, 0, 1, 1), 2, iterations = 1)
        val p = DoubleArray(2)
        assertEquals(0, model.predict(doubleArrayOf(0.2), p))
        assertEquals(Math.exp(1.0) / (Math.exp(1.0) + Math.exp(-1.0)), p[0], 1e-12)
        assertEquals(1, model.predict(doubleArrayOf(0.5000001), p))
        assertEquals(0, model.predict(doubleArrayOf(0.5), p)) // <= the cut goes left, as WEKA's whichSubset
    }

    @Test
    fun settings_outOfRange_areRejected() {
        assertThrows(IllegalArgumentException::class.java) { LogitBoost.Settings(iterations = 0) }
        assertThrows(IllegalArgumentException::class.java) { LogitBoost.Settings(shrinkage = 0.0) }
        assertThrows(IllegalArgumentException::class.java) { LogitBoost.Settings(zMax = Double.NaN) }
        assertThrows(IllegalArgumentException::class.java) { LogitBoost.Settings(weightThresholdPercent = 101) }
        assertEquals(LogitBoost.Settings(10, 1.0, 3.0, 100, -Double.MAX_VALUE), LogitBoost.WEKA_DEFAULTS)
    }

    @Test
    fun train_xorWithStumps_cannotBeatChance() {
        // An additive model of stumps has no interaction term: XOR stays at chance on the four corners.
        val rows = listOf(doubleArrayOf(0.0, 0.0), doubleArrayOf(0.0, 1.0), doubleArrayOf(1.0, 0.0), doubleArrayOf(1.0, 1.0))
        val labels = intArrayOf(0, 1, 1, 0)
        val model = LogitBoost.train(List(10) { rows }.flatten(), IntArray(40) { labels[it % 4] }, 2, iterations = 30)
        val p = DoubleArray(2)
        val right = rows.indices.count { model.predict(rows[it], p) == labels[it] }
        assertEquals(2, right)
    }

    @Test
    fun train_badInput_isRejected() {
        assertThrows(IllegalArgumentException::class.java) { LogitBoost.train(emptyList(), IntArray(0), 2) }
        assertThrows(IllegalArgumentException::class.java) { LogitBoost.train(listOf(doubleArrayOf(Double.NaN)), intArrayOf(0), 2) }
        assertThrows(IllegalArgumentException::class.java) { LogitBoost.train(listOf(doubleArrayOf(1.0)), intArrayOf(2), 2) }
        assertThrows(IllegalArgumentException::class.java) { LogitBoost.train(listOf(doubleArrayOf(1.0)), intArrayOf(0), 1) }
        assertThrows(IllegalArgumentException::class.java) { LogitBoost.train(listOf(doubleArrayOf(1.0), doubleArrayOf(1.0, 2.0)), intArrayOf(0, 1), 2) }
    }
}
