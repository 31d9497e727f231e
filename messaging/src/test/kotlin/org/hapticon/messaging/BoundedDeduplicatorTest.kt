package org.hapticon.messaging

import org.junit.Assert.assertEquals
import org.junit.Test

class BoundedDeduplicatorTest {
    @Test
    fun firstSeen_repeatedIds_trueOnlyTheFirstTime() {
        val dedupe = BoundedDeduplicator()
        assertEquals(listOf(true, true, false, false, true), listOf(ID_1, ID_2, ID_1, ID_2, "other").map(dedupe::firstSeen))
    }

    @Test
    fun firstSeen_beyondCapacity_forgetsTheLeastRecentlySeen() {
        val dedupe = BoundedDeduplicator(capacity = 2)
        dedupe.firstSeen("a")
        dedupe.firstSeen("b")
        dedupe.firstSeen("a") // a is now the most recent
        dedupe.firstSeen("c") // evicts b
        assertEquals(2, dedupe.size)
        assertEquals(listOf(false, false, true), listOf("a", "c", "b").map(dedupe::firstSeen))
    }

    @Test
    fun firstSeen_concurrentCallers_admitEachIdExactlyOnce() {
        val dedupe = BoundedDeduplicator()
        val admitted = java.util.concurrent.atomic.AtomicInteger()
        val threads = List(8) {
            Thread { repeat(1_000) { id -> if (dedupe.firstSeen("id-$id")) admitted.incrementAndGet() } }
        }
        threads.forEach(Thread::start)
        threads.forEach(Thread::join)
        assertEquals(1_000, admitted.get())
    }
}
