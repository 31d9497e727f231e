package org.hapticon.messaging

import kotlin.math.pow
import kotlin.random.Random

/**
 * When to try sending again after a failure: exponential backoff with jitter.
 *
 * After the n-th failed attempt the delay is `min(maxDelayMillis, initialDelayMillis · multiplier^(n−1))`,
 * shortened by a random fraction of up to [jitter] of itself, so that many phones coming back online at
 * once do not retry in lockstep. Pure: the randomness comes from [random], the time from the caller.
 */
public class RetryPolicy(
    private val initialDelayMillis: Long = 1_000,
    private val multiplier: Double = 2.0,
    private val maxDelayMillis: Long = 60_000,
    private val jitter: Double = 0.2,
    private val random: Random = Random.Default,
) {
    init {
        require(initialDelayMillis >= 1) { "initialDelayMillis must be >= 1, was $initialDelayMillis" }
        require(multiplier.isFinite() && multiplier >= 1.0) { "multiplier must be a finite number >= 1, was $multiplier" }
        require(maxDelayMillis >= initialDelayMillis) { "maxDelayMillis must be >= initialDelayMillis ($initialDelayMillis), was $maxDelayMillis" }
        require(jitter in 0.0..1.0) { "jitter must be in [0, 1], was $jitter" }
    }

    /**
     * The delay after the [failedAttempts]-th consecutive failure, in milliseconds, in
     * `[base·(1 − jitter), base]`. Throws [IllegalArgumentException] when [failedAttempts] < 1.
     */
    public fun delayMillis(failedAttempts: Int): Long {
        require(failedAttempts >= 1) { "failedAttempts must be >= 1, was $failedAttempts" }
        // Capped before multiplying out, so attempt 10_000 neither overflows nor turns infinite.
        val growth = multiplier.pow((failedAttempts - 1).coerceAtMost(MAX_EXPONENT))
        val base = minOf(maxDelayMillis.toDouble(), initialDelayMillis * growth)
        return maxOf(1L, (base * (1.0 - jitter * random.nextDouble())).toLong())
    }

    /** When to try again, given the time [nowMillis] of the [failedAttempts]-th failure. Throws as [delayMillis]. */
    public fun nextAttemptAt(nowMillis: Long, failedAttempts: Int): Long = nowMillis + delayMillis(failedAttempts)

    private companion object {
        const val MAX_EXPONENT = 64
    }
}
