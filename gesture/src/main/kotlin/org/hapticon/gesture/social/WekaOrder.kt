package org.hapticon.gesture.social

import java.util.Random

/**
 * The orders WEKA 3.8 (weka-stable 3.8.6, the paper's tool: 001_e790093bbd2e3cd3.txt:138) puts instances in, so that
 * [LogitBoost] adds the same numbers in the same order and [SocialTouchEvaluation] deals the same folds: WEKA's sums
 * are not reordered, so an order that differs changes the last bits, and a stump between two nearly equal splits can
 * then pick the other one. Each function names the WEKA source it follows (paths inside weka-stable-3.8.6-sources.jar).
 */
internal object WekaOrder {
    /**
     * Sorts [index] (positions into [values]) ascending by value: `weka/core/Utils.java` `quickSort(double[], int[], int,
     * int)` (lines 1869–1907): median of three, a partition around it, three or fewer sorted by compare-and-swap. Not
     * stable, which is why it is copied in behaviour rather than replaced by a library sort.
     */
    fun quickSort(values: DoubleArray, index: IntArray, left: Int, right: Int) {
        when (right - left) {
            0 -> return
            1 -> conditionalSwap(values, index, left, right)
            2 -> {
                conditionalSwap(values, index, left, left + 1)
                conditionalSwap(values, index, left, right)
                conditionalSwap(values, index, left + 1, right)
            }
            else -> {
                val pivot = sortLeftRightAndCentre(values, index, left, right)
                swap(index, pivot, right - 1)
                val centre = partition(values, index, left, right, values[index[right - 1]])
                swap(index, centre, right - 1)
                quickSort(values, index, left, centre - 1)
                quickSort(values, index, centre + 1, right)
            }
        }
    }

    /** `Utils.sortWithNoMissingValues` / `Utils.sort(double[])` (lines 1580–1609): the positions of [values] in ascending order. */
    fun sortedPositions(values: DoubleArray): IntArray {
        val index = IntArray(values.size) { it }
        if (values.size > 1) quickSort(values, index, 0, values.size - 1)
        return index
    }

    // Utils.java lines 1755–1787.
    private fun sortLeftRightAndCentre(values: DoubleArray, index: IntArray, l: Int, r: Int): Int {
        val c = (l + r) / 2
        conditionalSwap(values, index, l, c)
        conditionalSwap(values, index, l, r)
        conditionalSwap(values, index, c, r)
        return c
    }

    private fun conditionalSwap(values: DoubleArray, index: IntArray, left: Int, right: Int) {
        if (values[index[left]] > values[index[right]]) swap(index, left, right)
    }

    private fun swap(index: IntArray, l: Int, r: Int) {
        val help = index[l]; index[l] = index[r]; index[r] = help
    }

    // Utils.java lines 1799–1815: scans from both ends towards the pivot, which sits at r − 1.
    private fun partition(values: DoubleArray, index: IntArray, left: Int, right: Int, pivot: Double): Int {
        var l = left
        var r = right - 1
        while (true) {
            while (values[index[++l]] < pivot) Unit
            while (values[index[--r]] > pivot) Unit
            if (l >= r) return l
            swap(index, l, r)
        }
    }

    /** `weka/core/Instances.java` `randomize(Random)` (lines 1025–1030): a Fisher–Yates shuffle from the end. */
    fun randomize(order: IntArray, random: Random) {
        for (j in order.size - 1 downTo 1) swap(order, j, random.nextInt(j + 1))
    }

    /**
     * `Instances.stratify(int)` (lines 1754–1781) and `stratStep` (lines 2258–2273): gathers each class's instances
     * together by WEKA's in-place swaps, then deals them round robin so each fold's stretch holds every class.
     */
    fun stratify(order: IntArray, labels: IntArray, folds: Int): IntArray {
        val o = order.copyOf()
        var index = 1
        while (index < o.size) {
            val first = labels[o[index - 1]]
            for (j in index until o.size) {
                if (labels[o[j]] == first) {
                    swap(o, index, j)
                    index++
                }
            }
            index++
        }
        val out = IntArray(o.size)
        var filled = 0
        var start = 0
        while (filled < o.size) {
            var j = start
            while (j < o.size) { out[filled++] = o[j]; j += folds }
            start++
        }
        return out
    }

    /** `Instances.testCV(int, int)` (lines 1810–1833): fold [fold]'s contiguous stretch of [order]. */
    fun testFold(order: IntArray, folds: Int, fold: Int): IntArray {
        val (first, count) = stretch(order.size, folds, fold)
        return order.copyOfRange(first, first + count)
    }

    /** `Instances.trainCV(int, int, Random)` (lines 1889–1937): everything but fold [fold], then shuffled by [random]. */
    fun trainFold(order: IntArray, folds: Int, fold: Int, random: Random): IntArray {
        val (first, count) = stretch(order.size, folds, fold)
        val train = order.copyOfRange(0, first) + order.copyOfRange(first + count, order.size)
        randomize(train, random)
        return train
    }

    private fun stretch(n: Int, folds: Int, fold: Int): Pair<Int, Int> {
        var count = n / folds
        val offset: Int
        if (fold < n % folds) { count++; offset = fold } else offset = n % folds
        return (fold * (n / folds) + offset) to count
    }
}
