package org.hapticon.messaging

import org.junit.Assert.assertEquals
import org.junit.Test

class VibrationRateLimiterTest {
    private val clock = FakeClock(1_000_000)

    @Test
    fun tryAcquire_burstOfThreeFromOneSender_allowsThreeThenLimitsTheSender() {
        val limiter = VibrationRateLimiter(clock)
        val decisions = List(5) { limiter.tryAcquire("mallory", 100) }
        assertEquals(List(3) { VibrationDecision.VIBRATE } + List(2) { VibrationDecision.SENDER_LIMIT }, decisions)
    }

    @Test
    fun tryAcquire_afterTheRefillInterval_allowsExactlyOneMore() {
        val limiter = VibrationRateLimiter(clock)
        repeat(3) { limiter.tryAcquire("mallory", 100) }
        clock.advance(1_999)
        assertEquals(VibrationDecision.SENDER_LIMIT, limiter.tryAcquire("mallory", 100))
        clock.advance(1)
        assertEquals(VibrationDecision.VIBRATE, limiter.tryAcquire("mallory", 100))
        assertEquals(VibrationDecision.SENDER_LIMIT, limiter.tryAcquire("mallory", 100))
    }

    @Test
    fun tryAcquire_longIdle_refillsToTheBurstOnly() {
        val limiter = VibrationRateLimiter(clock)
        repeat(3) { limiter.tryAcquire("bob", 100) }
        clock.advance(3_600_000)
        assertEquals(3, limiter.availableFor("bob"))
        val decisions = List(4) { limiter.tryAcquire("bob", 100) }
        assertEquals(List(3) { VibrationDecision.VIBRATE } + VibrationDecision.SENDER_LIMIT, decisions)
    }

    @Test
    fun tryAcquire_oneSenderFlooding_doesNotLimitAnother() {
        val limiter = VibrationRateLimiter(clock)
        repeat(10) { limiter.tryAcquire("mallory", 100) }
        assertEquals(VibrationDecision.VIBRATE, limiter.tryAcquire("alice", 100))
        assertEquals(0, limiter.availableFor("mallory"))
        assertEquals(2, limiter.availableFor("alice"))
    }

    @Test
    fun tryAcquire_manySendersTogether_areCappedByTheDutyCycle() {
        // 30 s of vibration per 60 s window: three 10 s icons fill it, the fourth is refused.
        val limiter = VibrationRateLimiter(clock, dutyWindowMillis = 60_000, maxDutyCycle = 0.5)
        val decisions = listOf("a", "b", "c", "d").map { limiter.tryAcquire(it, 10_000) }
        assertEquals(List(3) { VibrationDecision.VIBRATE } + VibrationDecision.DUTY_CYCLE_LIMIT, decisions)
        // Refused requests consume nothing: d still has its whole burst.
        assertEquals(3, limiter.availableFor("d"))
    }

    @Test
    fun tryAcquire_whenTheFirstGrantLeavesTheWindow_allowsAgain() {
        val limiter = VibrationRateLimiter(clock, dutyWindowMillis = 60_000, maxDutyCycle = 0.5)
        limiter.tryAcquire("a", 20_000)
        clock.advance(30_000)
        limiter.tryAcquire("b", 10_000)
        assertEquals(VibrationDecision.DUTY_CYCLE_LIMIT, limiter.tryAcquire("c", 1))
        clock.advance(29_999)
        assertEquals(VibrationDecision.DUTY_CYCLE_LIMIT, limiter.tryAcquire("c", 1))
        clock.advance(1) // a's grant started 60 s ago: out of the window
        assertEquals(VibrationDecision.VIBRATE, limiter.tryAcquire("c", 20_000))
        assertEquals(VibrationDecision.DUTY_CYCLE_LIMIT, limiter.tryAcquire("d", 1))
    }

    @Test
    fun tryAcquire_clockSteppingBack_countsAsNoTimePassing() {
        val limiter = VibrationRateLimiter(clock)
        repeat(3) { limiter.tryAcquire("bob", 100) }
        clock.advance(-10_000_000)
        assertEquals(VibrationDecision.SENDER_LIMIT, limiter.tryAcquire("bob", 100))
        clock.advance(10_000_000 + 2_000) // back to where it was, plus one interval
        assertEquals(VibrationDecision.VIBRATE, limiter.tryAcquire("bob", 100))
    }

    @Test
    fun tryAcquire_moreSendersThanTracked_forgetsFullBucketsFirst() {
        val limiter = VibrationRateLimiter(clock, maxTrackedSenders = 2, maxDutyCycle = 1.0)
        repeat(3) { limiter.tryAcquire("drained", 1) }
        limiter.tryAcquire("full-again", 1)
        clock.advance(2_000) // full-again refills completely; drained only to one token
        limiter.tryAcquire("newcomer", 1)
        assertEquals(1, limiter.availableFor("drained"))
    }

    @Test
    fun tryAcquire_zeroLengthIcons_stillCountAgainstTheDutyCycle() {
        val limiter = VibrationRateLimiter(clock, burst = 100, dutyWindowMillis = 10, maxDutyCycle = 0.5)
        val allowed = List(10) { limiter.tryAcquire("a", 0) }.count { it == VibrationDecision.VIBRATE }
        assertEquals(5, allowed)
    }
}
