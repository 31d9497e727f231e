package org.hapticon.study.design

import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Assert.assertThrows
import org.junit.Test

class CounterbalancingTest {
    @Test
    fun williams_evenAndOddN_everyOrderedPairAdjacentEquallyOften() {
        for (n in 2..7) {
            val rows = Counterbalancing.williamsSquare(n)
            assertEquals("rows for n=$n", if (n % 2 == 0) n else 2 * n, rows.size)
            val adjacent = HashMap<Pair<Int, Int>, Int>()
            for (row in rows) {
                assertEquals("row $row is a permutation", (0 until n).toList(), row.sorted())
                row.zipWithNext().forEach { adjacent.merge(it, 1, Int::plus) }
            }
            val expected = if (n % 2 == 0) 1 else 2
            for (a in 0 until n) for (b in 0 until n) {
                if (a != b) assertEquals("n=$n: $a directly before $b", expected, adjacent[a to b] ?: 0)
            }
            assertEquals(n * (n - 1), adjacent.size)
        }
    }

    @Test
    fun williams_fourItems_exactSquare() {
        assertEquals(
            listOf(listOf(0, 1, 3, 2), listOf(1, 2, 0, 3), listOf(2, 3, 1, 0), listOf(3, 0, 2, 1)),
            Counterbalancing.williamsSquare(4),
        )
    }

    @Test
    fun williams_threeItems_squareThenMirror() {
        assertEquals(
            listOf(listOf(0, 1, 2), listOf(1, 2, 0), listOf(2, 0, 1), listOf(2, 1, 0), listOf(0, 2, 1), listOf(1, 0, 2)),
            Counterbalancing.williamsSquare(3),
        )
    }

    @Test
    fun everyBalancedScheme_overOneCycle_everyItemInEveryPositionEquallyOften() {
        for (scheme in listOf(OrderScheme.PAPER, OrderScheme.FULL, OrderScheme.WILLIAMS)) {
            for (n in 1..6) {
                val cycle = Counterbalancing.cycleLength(scheme, n)!!.toInt()
                val counts = Array(n) { IntArray(n) }
                for (p in 0 until cycle) {
                    Counterbalancing.order(scheme, n, p).forEachIndexed { position, item -> counts[item][position]++ }
                }
                for (item in 0 until n) for (position in 0 until n) {
                    assertEquals("$scheme n=$n item $item at $position", cycle / n, counts[item][position])
                }
            }
        }
    }

    @Test
    fun full_hasNFactorialDistinctRowsInLexicographicOrder() {
        for (n in 1..6) {
            val cycle = Counterbalancing.cycleLength(OrderScheme.FULL, n)!!.toInt()
            val rows = (0 until cycle).map { Counterbalancing.order(OrderScheme.FULL, n, it) }
            assertEquals(listOf(1, 2, 6, 24, 120, 720)[n - 1], rows.toSet().size)
            assertEquals(rows, rows.sortedWith { a, b -> a.zip(b).map { (x, y) -> x.compareTo(y) }.firstOrNull { it != 0 } ?: 0 })
            assertEquals("cycles", rows[0], Counterbalancing.order(OrderScheme.FULL, n, cycle))
        }
        assertEquals(listOf(2, 0, 1), Counterbalancing.order(OrderScheme.FULL, 3, 4))
    }

    @Test
    fun full_twentyItems_hugeIndexStillAPermutation() {
        val order = Counterbalancing.order(OrderScheme.FULL, 20, Int.MAX_VALUE)
        assertEquals((0 until 20).toList(), order.sorted())
        assertEquals(2_432_902_008_176_640_000L, Counterbalancing.cycleLength(OrderScheme.FULL, 20))
    }

    @Test
    fun full_twentyOneItems_rejected() {
        val e = assertThrows(IllegalArgumentException::class.java) { Counterbalancing.order(OrderScheme.FULL, 21, 0) }
        assertEquals("full counterbalancing of 21 items needs 21! participants; at most 20 items", e.message)
    }

    @Test
    fun paper_twoItems_alternates() {
        assertEquals(listOf(0, 1), Counterbalancing.order(OrderScheme.PAPER, 2, 0))
        assertEquals(listOf(1, 0), Counterbalancing.order(OrderScheme.PAPER, 2, 1))
        assertEquals(listOf(0, 1), Counterbalancing.order(OrderScheme.PAPER, 2, 2))
        assertEquals(listOf(2, 0, 1), Counterbalancing.order(OrderScheme.PAPER, 3, 2))
    }

    @Test
    fun random_sameSeedSameOrder_differentSeedsDiffer() {
        val a = (0 until 50).map { Counterbalancing.order(OrderScheme.RANDOM, 8, it, seed = 42) }
        val b = (0 until 50).map { Counterbalancing.order(OrderScheme.RANDOM, 8, it, seed = 42) }
        val c = (0 until 50).map { Counterbalancing.order(OrderScheme.RANDOM, 8, it, seed = 43) }
        assertEquals(a, b)
        assertNotEquals(a, c)
        a.forEach { assertEquals((0 until 8).toList(), it.sorted()) }
        assertTrue("participants differ", a.toSet().size > 40)
        assertNotEquals(
            Counterbalancing.order(OrderScheme.RANDOM, 8, 0, seed = 42, stream = 0),
            Counterbalancing.order(OrderScheme.RANDOM, 8, 0, seed = 42, stream = 1),
        )
        assertNull(Counterbalancing.cycleLength(OrderScheme.RANDOM, 8))
    }

    @Test
    fun random_pinnedValues_stableAcrossJvms() {
        // Pinned: SplitMix64 is fixed arithmetic, so these may only change with a deliberate algorithm change.
        assertEquals(PINNED_SEED_42_P0, Counterbalancing.order(OrderScheme.RANDOM, 6, 0, seed = 42))
        assertEquals(PINNED_SEED_MIN_P1, Counterbalancing.order(OrderScheme.RANDOM, 6, 1, seed = Long.MIN_VALUE))
    }

    @Test
    fun random_positionsRoughlyUniform() {
        val counts = Array(4) { IntArray(4) }
        for (p in 0 until 40_000) Counterbalancing.order(OrderScheme.RANDOM, 4, p, seed = 7).forEachIndexed { pos, item -> counts[item][pos]++ }
        for (item in 0 until 4) for (pos in 0 until 4) assertTrue("${counts[item][pos]}", counts[item][pos] in 9_600..10_400)
    }

    @Test
    fun edges_zeroAndOneItem_andBadArguments() {
        for (scheme in OrderScheme.entries) {
            assertEquals(emptyList<Int>(), Counterbalancing.order(scheme, 0, 3))
            assertEquals(listOf(0), Counterbalancing.order(scheme, 1, 3))
        }
        assertEquals(listOf(listOf(0)), Counterbalancing.williamsSquare(1))
        assertEquals("participantIndex must be >= 0, was -1", assertThrows(IllegalArgumentException::class.java) { Counterbalancing.order(OrderScheme.PAPER, 3, -1) }.message)
        assertEquals("itemCount must be >= 0, was -1", assertThrows(IllegalArgumentException::class.java) { Counterbalancing.order(OrderScheme.PAPER, -1, 0) }.message)
    }

    @Test
    fun fromJsonName_caseInsensitive_unknownIsNull() {
        assertEquals(OrderScheme.WILLIAMS, OrderScheme.fromJsonName("Williams"))
        assertNull(OrderScheme.fromJsonName("latin"))
    }

    private companion object {
        val PINNED_SEED_42_P0 = listOf(0, 4, 5, 1, 2, 3)
        val PINNED_SEED_MIN_P1 = listOf(1, 2, 5, 4, 0, 3)
    }
}
