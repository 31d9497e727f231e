package org.hapticon.companion.chat.load

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

class DeliveryLedgerTest {
    @Test
    fun tally_countsEachMessageOnce_lostDuplicatedUnexpectedMisroutedAndFailedApart() {
        val ledger = DeliveryLedger()
        ledger.sent("a", "bob", nanos = 1_000_000)
        ledger.sent("b", "bob", nanos = 2_000_000)
        ledger.sent("c", "carol", nanos = 3_000_000)
        ledger.sent("d", "carol", nanos = 4_000_000)
        ledger.sent("e", "dave", nanos = 5_000_000)
        listOf("a", "b", "c").forEach(ledger::acknowledged)
        ledger.failed("d")
        ledger.received("a", "bob", nanos = 4_000_000) // 3 ms
        ledger.received("a", "bob", nanos = 9_000_000) // duplicate: its latency is the first arrival's
        ledger.received("a", "bob", nanos = 9_500_000) // a second duplicate
        ledger.received("b", "carol", nanos = 9_000_000) // misrouted: b was for bob
        ledger.received("zzz", "bob", nanos = 9_000_000) // nobody sent zzz

        val tally = ledger.tally()
        assertEquals(5, tally.sent)
        assertEquals(3, tally.acknowledged)
        assertEquals(1, tally.failed)
        assertEquals(1, tally.delivered)
        assertEquals(2, tally.lost) // b and c: acknowledged, never arrived at their recipient
        assertEquals(1, tally.pending) // e: neither acknowledged nor failed
        assertEquals(2, tally.duplicates)
        assertEquals(1, tally.unexpected)
        assertEquals(1, tally.misrouted)
        assertEquals(LatencySummary(1, 3.0, 3.0, 3.0), tally.allMillis)
        assertFalse(tally.allAccountedFor)
        assertEquals(2, ledger.outstanding())
    }

    @Test
    fun allAccountedFor_holdsWhenEveryMessageArrivedOnceOrFailedVisibly() {
        val ledger = DeliveryLedger()
        ledger.sent("a", "bob", nanos = 0)
        ledger.sent("b", "bob", nanos = 0)
        ledger.sent("c", "bob", nanos = 0)
        ledger.acknowledged("a")
        ledger.received("a", "bob", nanos = 5_000_000)
        // A publish that threw but reached the broker anyway is delivered, not lost.
        ledger.failed("b")
        ledger.received("b", "bob", nanos = 6_000_000)
        ledger.failed("c")
        val tally = ledger.tally()
        assertTrue(tally.toString(), tally.allAccountedFor)
        assertEquals(2, tally.delivered)
        assertEquals(0, tally.lost)
        assertEquals(0, ledger.outstanding())

        ledger.received("a", "bob", nanos = 7_000_000)
        assertFalse("a duplicate breaks it", ledger.tally().allAccountedFor)
    }

    @Test
    fun tally_separatesBurstFromSteadyLatencies_andMergesThemForAll() {
        val ledger = DeliveryLedger()
        for ((i, ms) in listOf(1, 2, 3).withIndex()) {
            ledger.sent("s$i", "bob", nanos = 0)
            ledger.acknowledged("s$i")
            ledger.received("s$i", "bob", nanos = ms * 1_000_000L)
        }
        for ((i, ms) in listOf(10, 40).withIndex()) {
            ledger.sent("b$i", "bob", nanos = 1_000_000, burst = true)
            ledger.acknowledged("b$i")
            ledger.received("b$i", "bob", nanos = 1_000_000 + ms * 1_000_000L)
        }
        val tally = ledger.tally()
        assertEquals(LatencySummary(3, 2.0, 3.0, 3.0), tally.steadyMillis)
        assertEquals(LatencySummary(2, 10.0, 40.0, 40.0), tally.burstMillis)
        assertEquals(LatencySummary(5, 3.0, 40.0, 40.0), tally.allMillis)
    }

    @Test(expected = IllegalStateException::class)
    fun sent_sameIdTwice_isABugOfTheBench() {
        val ledger = DeliveryLedger()
        ledger.sent("a", "bob", nanos = 0)
        ledger.sent("a", "bob", nanos = 1)
    }

    @Test
    fun nearestRank_isAMeasuredValue_rankCeilOfPTimesN() {
        val hundred = (1..100).map { it.toDouble() }
        assertEquals(50.0, LatencySummary.nearestRank(hundred, 0.50), 0.0)
        assertEquals(99.0, LatencySummary.nearestRank(hundred, 0.99), 0.0)
        assertEquals(100.0, LatencySummary.nearestRank(hundred, 1.0), 0.0)
        // 1,000 values: p99 is the 990th, so ten slow ones show and nine do not.
        val thousand = List(990) { 1.0 } + List(10) { 80.0 }
        assertEquals(1.0, LatencySummary.nearestRank(thousand, 0.99), 0.0)
        assertEquals(80.0, LatencySummary.nearestRank(List(989) { 1.0 } + List(11) { 80.0 }, 0.99), 0.0)
        assertEquals(7.0, LatencySummary.nearestRank(listOf(7.0), 0.01), 0.0)
        val summary = LatencySummary.of(listOf(5.0, 1.0, 3.0, 2.0, 4.0))
        assertEquals(LatencySummary(5, 3.0, 5.0, 5.0), summary)
        assertEquals(0, LatencySummary.of(emptyList()).count)
        assertTrue(LatencySummary.of(emptyList()).p99.isNaN())
    }
}
