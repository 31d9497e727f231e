package org.hapticon.study.design

/**
 * Orders of n items by participant index, as pure functions: the same scheme, n, index and seed always give the
 * same order. An order is a permutation of 0 until n: element k is the index of the item shown k-th.
 */
public object Counterbalancing {
    /** Largest n for [OrderScheme.FULL]: 20! is the largest factorial that fits in a Long. */
    public const val MAX_FULL_ITEMS: Int = 20

    /**
     * The order of [itemCount] items for the participant with 0-based [participantIndex] under [scheme]. [seed] is
     * used by [OrderScheme.RANDOM] only; [stream] separates independent random orders of one participant (for example
     * the tasks and each task's stimuli) so that they are not the same shuffle.
     *
     * Throws [IllegalArgumentException] when [itemCount] is negative, [participantIndex] is negative, or
     * [itemCount] exceeds [MAX_FULL_ITEMS] for [OrderScheme.FULL].
     */
    public fun order(scheme: OrderScheme, itemCount: Int, participantIndex: Int, seed: Long = 0L, stream: Int = 0): List<Int> {
        require(itemCount >= 0) { "itemCount must be >= 0, was $itemCount" }
        require(participantIndex >= 0) { "participantIndex must be >= 0, was $participantIndex" }
        if (itemCount == 0) return emptyList()
        return when (scheme) {
            OrderScheme.FIXED -> List(itemCount) { it }
            OrderScheme.PAPER -> List(itemCount) { (it + participantIndex) % itemCount }
            OrderScheme.FULL -> permutation(itemCount, participantIndex.toLong() % factorial(itemCount))
            OrderScheme.WILLIAMS -> williamsRow(itemCount, participantIndex % williamsRows(itemCount))
            OrderScheme.RANDOM -> shuffled(itemCount, seed, participantIndex, stream)
        }
    }

    /**
     * How many participants one balanced cycle of [scheme] takes for [itemCount] items: 1 for fixed, n for paper,
     * n! for full, n or 2n for Williams; null for random, which has no cycle. Throws like [order].
     */
    public fun cycleLength(scheme: OrderScheme, itemCount: Int): Long? {
        require(itemCount >= 0) { "itemCount must be >= 0, was $itemCount" }
        val n = maxOf(itemCount, 1)
        return when (scheme) {
            OrderScheme.FIXED -> 1L
            OrderScheme.PAPER -> n.toLong()
            OrderScheme.FULL -> factorial(n)
            OrderScheme.WILLIAMS -> williamsRows(n).toLong()
            OrderScheme.RANDOM -> null
        }
    }

    /**
     * The Williams square for [itemCount] items, all rows: the first row is 0, 1, n−1, 2, n−2, ..., row r adds r
     * mod n to every element; for odd n the mirrored rows follow, since no single n-row square is balanced then.
     * Throws [IllegalArgumentException] when [itemCount] < 1.
     */
    public fun williamsSquare(itemCount: Int): List<List<Int>> {
        require(itemCount >= 1) { "itemCount must be >= 1, was $itemCount" }
        return List(williamsRows(itemCount)) { williamsRow(itemCount, it) }
    }

    // One item needs no mirror: there are no pairs to balance.
    private fun williamsRows(n: Int): Int = if (n % 2 == 0 || n == 1) n else 2 * n

    private fun williamsRow(n: Int, row: Int): List<Int> {
        val shift = row % n
        val first = IntArray(n)
        var low = 1
        var high = n - 1
        for (k in 1 until n) first[k] = if (k % 2 == 1) low++ else high--
        val square = List(n) { (first[it] + shift) % n }
        return if (row < n) square else square.asReversed().toList()
    }

    /** The [rank]-th permutation of 0 until [n] in lexicographic order, from its factorial-base digits. */
    private fun permutation(n: Int, rank: Long): List<Int> {
        require(n <= MAX_FULL_ITEMS) { "full counterbalancing of $n items needs $n! participants; at most $MAX_FULL_ITEMS items" }
        val remaining = MutableList(n) { it }
        var r = rank
        return List(n) { k ->
            val f = factorial(n - 1 - k)
            val digit = (r / f).toInt()
            r %= f
            remaining.removeAt(digit)
        }
    }

    private fun factorial(n: Int): Long {
        require(n <= MAX_FULL_ITEMS) { "full counterbalancing of $n items needs $n! participants; at most $MAX_FULL_ITEMS items" }
        var f = 1L
        for (k in 2..n) f *= k
        return f
    }

    private fun shuffled(n: Int, seed: Long, participantIndex: Int, stream: Int): List<Int> {
        // Each (seed, participant, stream) gets its own generator; mixing keeps neighbouring indices unrelated.
        val random = SplitMix64(SplitMix64.mix(SplitMix64.mix(seed) + participantIndex.toLong() * 0x100000001L + stream))
        val order = IntArray(n) { it }
        for (i in n - 1 downTo 1) {
            val j = random.nextInt(i + 1)
            val t = order[i]; order[i] = order[j]; order[j] = t
        }
        return order.toList()
    }
}
