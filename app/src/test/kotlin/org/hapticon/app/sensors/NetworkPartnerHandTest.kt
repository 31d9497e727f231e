package org.hapticon.app.sensors

import org.hapticon.messaging.HandPose
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

class NetworkPartnerHandTest {
    private val hand = NetworkPartnerHand("bob")
    private val out = DoubleArray(2)

    private fun read(nowNanos: Long): DoubleArray {
        hand.readAngles(nowNanos, out)
        return out.copyOf()
    }

    @Test
    fun nothingHeard_isAnOpenHand() {
        assertArrayEquals(doubleArrayOf(0.0, 0.0), read(0), 0.0)
        assertFalse(hand.isLive(0))
    }

    @Test
    fun freshPose_isTheirHand_untilHalfASecondOfSilenceOpensIt() {
        hand.offer(HandPose("bob", 40.0, 70.0, 1_000), receivedNanos = 1_000_000_000)

        assertArrayEquals(doubleArrayOf(40.0, 70.0), read(1_500_000_000), 0.0)
        assertTrue(hand.isLive(1_500_000_000))
        assertArrayEquals(doubleArrayOf(0.0, 0.0), read(1_500_000_001), 0.0)
        assertFalse(hand.isLive(1_500_000_001))
    }

    @Test
    fun olderPoseArrivingLate_doesNotUndoANewerOne() {
        hand.offer(HandPose("bob", 40.0, 70.0, 2_000), receivedNanos = 10)
        hand.offer(HandPose("bob", 5.0, 5.0, 1_967), receivedNanos = 20)

        assertArrayEquals(doubleArrayOf(40.0, 70.0), read(30), 0.0)
    }

    @Test
    fun someoneElsesPose_isIgnored() {
        hand.offer(HandPose("mallory", 90.0, 90.0, 1), receivedNanos = 10)

        assertArrayEquals(doubleArrayOf(0.0, 0.0), read(20), 0.0)
    }
}
