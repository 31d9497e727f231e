package org.hapticon.messaging

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class RetryPolicyTest {
    @Test
    fun delayMillis_withoutJitterDraw_doublesFromTheInitialDelayUpToTheCap() {
        val policy = RetryPolicy(initialDelayMillis = 1_000, multiplier = 2.0, maxDelayMillis = 60_000, jitter = 0.2, random = FixedRandom(0.0))
        assertEquals(listOf(1_000L, 2_000, 4_000, 8_000, 16_000, 32_000, 60_000, 60_000), (1..8).map(policy::delayMillis))
    }

    @Test
    fun delayMillis_jitterDraw_shortensTheDelayByThatShareOfTheJitter() {
        val policy = RetryPolicy(initialDelayMillis = 1_000, maxDelayMillis = 60_000, jitter = 0.2, random = FixedRandom(0.5))
        assertEquals(listOf(900L, 1_800, 3_600), (1..3).map(policy::delayMillis))
        assertEquals(54_000L, policy.delayMillis(20))
    }

    @Test
    fun delayMillis_hugeAttemptCount_staysAtTheCap() {
        val policy = RetryPolicy(initialDelayMillis = 1_000, maxDelayMillis = 60_000, jitter = 0.0)
        assertEquals(60_000L, policy.delayMillis(Int.MAX_VALUE))
    }

    @Test
    fun delayMillis_seededRandom_staysWithinTheJitterBand() {
        val policy = RetryPolicy(initialDelayMillis = 1_000, maxDelayMillis = 60_000, jitter = 0.2, random = kotlin.random.Random(42))
        val delays = List(1_000) { policy.delayMillis(3) }
        assertEquals(emptyList<Long>(), delays.filter { it !in 3_200L..4_000L })
        // Not all equal: the jitter spreads retries.
        assertEquals(true, delays.toSet().size > 100)
    }

    @Test
    fun nextAttemptAt_addsTheDelayToNow() {
        val policy = RetryPolicy(initialDelayMillis = 500, jitter = 0.0)
        assertEquals(10_000L + 1_000, policy.nextAttemptAt(10_000, 2))
    }

    @Test
    fun constructorAndDelay_invalidArguments_throw() {
        assertThrows(IllegalArgumentException::class.java) { RetryPolicy(initialDelayMillis = 0) }
        assertThrows(IllegalArgumentException::class.java) { RetryPolicy(multiplier = 0.5) }
        assertThrows(IllegalArgumentException::class.java) { RetryPolicy(initialDelayMillis = 10, maxDelayMillis = 5) }
        assertThrows(IllegalArgumentException::class.java) { RetryPolicy(jitter = 1.5) }
        assertThrows(IllegalArgumentException::class.java) { RetryPolicy().delayMillis(0) }
    }
}
