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
    fun train_nonSeparableIdenticalRows_learnsTheClassFrequencies() {
        // 30 × class 0 and 10 × class 1 with the same features: no stump can split, so p → (0.75, 0.25).
        val rows = List(40) { doubleArrayOf(1.0, 2.0) }
        val labels = IntArray(40) { if (it < 30) 0 else 1 }
        val model = LogitBoost.train(rows, labels, 2, iterations = 50)
        val p = DoubleArray(2)
        assertEquals(0, model.predict(doubleArrayOf(1.0, 2.0), p))
        assertEquals(0.75, p[0], 1e-6)
        assertEquals(0.25, p[1], 1e-6)
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
