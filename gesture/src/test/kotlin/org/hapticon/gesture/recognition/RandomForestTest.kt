package org.hapticon.gesture.recognition

import org.hapticon.core.io.Json
import org.hapticon.core.io.SchemaJson
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class RandomForestTest {
    // Class = quadrant of (x, y) around (5, 5); a third feature is noise.
    private val rows = (0 until 200).map { i -> doubleArrayOf((i * 37 % 100) / 10.0, (i * 61 % 100) / 10.0, (i * 13 % 7).toDouble()) }
    private val labels = IntArray(rows.size) { (if (rows[it][0] > 5) 1 else 0) + (if (rows[it][1] > 5) 2 else 0) }

    private fun train(seed: Long, trees: Int = 20) = RandomForest.train(rows, labels, 4, ForestParams(trees = trees, seed = seed, featuresPerSplit = 2))

    @Test
    fun learnsSeparableQuadrants() {
        val forest = train(seed = 7)
        val p = DoubleArray(4)
        assertEquals(0, forest.predict(doubleArrayOf(1.0, 1.0, 3.0), p))
        assertEquals(1, forest.predict(doubleArrayOf(9.0, 1.0, 3.0), p))
        assertEquals(2, forest.predict(doubleArrayOf(1.0, 9.0, 3.0), p))
        assertEquals(3, forest.predict(doubleArrayOf(9.0, 9.0, 3.0), p))
        assertEquals(1.0, p.sum(), 1e-12)
        assertEquals(0.95, p[3], 0.0) // 19 of 20 trees (seed 7)
    }

    @Test
    fun train_minSamplesSplitAboveTheSampleCount_growsOnlyRoots() {
        val forest = RandomForest.train(rows, labels, 4, ForestParams(trees = 3, minSamplesSplit = 201, bootstrap = false))
        // 200 samples are fewer than 201: no node may split, so each tree is one leaf.
        assertEquals(3, forest.nodeCount)
        // 200 samples may split once (depth 1): a root and two leaves.
        assertEquals(3, RandomForest.train(rows, labels, 4, ForestParams(trees = 1, minSamplesSplit = 200, maxDepth = 1, bootstrap = false, featuresPerSplit = 3)).nodeCount)
    }

    @Test
    fun train_withoutBootstrapAndAllFeatures_treesAgreeEverywhere() {
        // Every tree sees every sample and every feature, so the seed no longer matters: all votes are unanimous.
        val forest = RandomForest.train(rows, labels, 4, ForestParams(trees = 3, bootstrap = false, featuresPerSplit = 3))
        val p = DoubleArray(4)
        for (row in rows) {
            forest.predict(row, p)
            assertEquals(1.0, p.max(), 0.0)
        }
    }

    @Test
    fun params_minSamplesSplitBelowTwo_isRejected() {
        assertThrows(IllegalArgumentException::class.java) { ForestParams(minSamplesSplit = 1) }
    }

    @Test
    fun sameSeedSameForestOtherSeedOtherForest() {
        val a = SchemaJson.encodeElement(train(seed = 3).toJson())
        assertEquals(a, SchemaJson.encodeElement(train(seed = 3).toJson()))
        assertNotEquals(a, SchemaJson.encodeElement(train(seed = 4).toJson()))
    }

    @Test
    fun firstTreesEqualsTrainingFewerTrees() {
        assertEquals(SchemaJson.encodeElement(train(seed = 5, trees = 4).toJson()), SchemaJson.encodeElement(train(seed = 5, trees = 20).firstTrees(4).toJson()))
    }

    @Test
    fun jsonRoundTripPredictsIdentically() {
        val forest = train(seed = 11)
        val restored = RandomForest.fromJson(Json.decode(SchemaJson.encodeElement(forest.toJson())))
        val p = DoubleArray(4)
        val q = DoubleArray(4)
        for (i in 0 until 100) {
            val x = doubleArrayOf(i / 10.0, (99 - i) / 10.0, (i % 7).toDouble())
            assertEquals(forest.predict(x, p), restored.predict(x, q))
            assertArrayEquals(p, q, 0.0)
        }
        assertEquals(forest.nodeCount, restored.nodeCount)
    }

    @Test
    fun depthOneGivesStumps() {
        val forest = RandomForest.train(rows, labels, 4, ForestParams(trees = 3, maxDepth = 1, seed = 1))
        assertEquals(9, forest.nodeCount) // a root and two leaves each
    }

    @Test
    fun oneSampleAndOneClassGiveALeaf() {
        val forest = RandomForest.train(listOf(doubleArrayOf(1.0)), intArrayOf(2), 3, ForestParams(trees = 2))
        val p = DoubleArray(3)
        assertEquals(2, forest.predict(doubleArrayOf(-1e300), p))
        assertArrayEquals(doubleArrayOf(0.0, 0.0, 1.0), p, 0.0)
    }

    @Test
    fun rejectsBadInput() {
        val params = ForestParams(trees = 1)
        assertThrows(IllegalArgumentException::class.java) { RandomForest.train(emptyList(), IntArray(0), 2, params) }
        assertThrows(IllegalArgumentException::class.java) { RandomForest.train(listOf(doubleArrayOf(Double.NaN)), intArrayOf(0), 2, params) }
        assertThrows(IllegalArgumentException::class.java) { RandomForest.train(listOf(doubleArrayOf(1.0), doubleArrayOf(1.0, 2.0)), intArrayOf(0, 1), 2, params) }
        assertThrows(IllegalArgumentException::class.java) { RandomForest.train(listOf(doubleArrayOf(1.0)), intArrayOf(2), 2, params) }
        assertThrows(IllegalArgumentException::class.java) { ForestParams(trees = 0) }
        val forest = train(seed = 1)
        assertThrows(IllegalArgumentException::class.java) { forest.predict(DoubleArray(2), DoubleArray(4)) }
    }

    @Test
    fun rejectsATreeWhoseChildrenLoop() {
        val loop = """{"featureCount":1,"classCount":2,"trees":[{"feature":[0,-1],"threshold":[0.5,0],"left":[0,0],"right":[1,0]}]}"""
        val e = assertThrows(IllegalArgumentException::class.java) { RandomForest.fromJson(Json.decode(loop)) }
        assertEquals("trees[0]: node 0 has children outside 1 until 2", e.message)
    }
}
