package org.hapticon.messaging

import java.util.ArrayDeque

/**
 * Decides whether an incoming icon may vibrate now, so that no sender, and no crowd of senders, can keep
 * the phone buzzing. Messages over the limit are still stored and shown; only the vibration is skipped.
 *
 * Two limits apply, both must allow:
 * - per sender, a token bucket: [burst] vibrations at once, refilled by one every [refillIntervalMillis];
 * - overall, a duty cycle: vibrations that started in the last [dutyWindowMillis] (counting the new one)
 *   may add up to at most [maxDutyCycle] of that window.
 *
 * A refused request consumes nothing. Pure apart from [clock], which should be monotonic
 * ([Clock.MONOTONIC]); a clock that steps back counts as no time passing. Thread-safe; never blocks.
 *
 * Memory is bounded: at most [maxTrackedSenders] buckets are kept. Full buckets carry no state and are
 * dropped first; beyond that the least recently used sender is forgotten (it gets a fresh burst, which
 * the duty-cycle cap still bounds).
 */
public class VibrationRateLimiter(
    private val clock: Clock,
    private val burst: Int = 3,
    private val refillIntervalMillis: Long = 2_000,
    private val dutyWindowMillis: Long = 60_000,
    private val maxDutyCycle: Double = 0.5,
    private val maxTrackedSenders: Int = 1_024,
) {
    init {
        require(burst >= 1) { "burst must be >= 1, was $burst" }
        require(refillIntervalMillis >= 1) { "refillIntervalMillis must be >= 1, was $refillIntervalMillis" }
        require(dutyWindowMillis >= 1) { "dutyWindowMillis must be >= 1, was $dutyWindowMillis" }
        require(maxDutyCycle > 0.0 && maxDutyCycle <= 1.0) { "maxDutyCycle must be in (0, 1], was $maxDutyCycle" }
        require(maxTrackedSenders >= 1) { "maxTrackedSenders must be >= 1, was $maxTrackedSenders" }
    }

    // Token-bucket state in milliseconds of credit: a vibration costs refillIntervalMillis, the bucket holds
    // burst of them and gains one millisecond per millisecond. Integer arithmetic, so tests are exact.
    private class Bucket(var creditMillis: Long, var updatedAtMillis: Long)

    private val capacityMillis = burst * refillIntervalMillis
    private val buckets = LinkedHashMap<String, Bucket>(16, 0.75f, true) // access order: eldest = least recently used
    private val dutyBudgetMillis = (dutyWindowMillis * maxDutyCycle).toLong()
    private val grants = ArrayDeque<LongArray>() // (start, duration) of vibrations within the window, oldest first
    private var grantedInWindowMillis = 0L
    private var lastNowMillis = Long.MIN_VALUE

    /**
     * Asks to vibrate an icon of [durationMillis] from [sender] now. Returns [VibrationDecision.VIBRATE] and
     * records it, or the limit that refuses it. Throws [IllegalArgumentException] when [durationMillis] is negative.
     */
    @Synchronized
    public fun tryAcquire(sender: String, durationMillis: Long): VibrationDecision {
        require(durationMillis >= 0) { "durationMillis must be >= 0, was $durationMillis" }
        val now = monotonicNow()
        val bucket = refilledBucket(sender, now)
        if (bucket.creditMillis < refillIntervalMillis) return VibrationDecision.SENDER_LIMIT
        expireGrants(now)
        // An empty icon still counts a millisecond, so the window holds at most dutyBudgetMillis grants.
        val cost = maxOf(durationMillis, 1)
        if (grantedInWindowMillis + cost > dutyBudgetMillis) return VibrationDecision.DUTY_CYCLE_LIMIT
        bucket.creditMillis -= refillIntervalMillis
        grants.addLast(longArrayOf(now, cost))
        grantedInWindowMillis += cost
        return VibrationDecision.VIBRATE
    }

    /** Vibrations [sender] could start right now as far as its own bucket goes (0..burst). Does not consume any. */
    @Synchronized
    public fun availableFor(sender: String): Int {
        val bucket = buckets[sender] ?: return burst
        val elapsed = (monotonicNow() - bucket.updatedAtMillis).coerceAtLeast(0)
        return (minOf(capacityMillis, bucket.creditMillis + elapsed) / refillIntervalMillis).toInt()
    }

    private fun monotonicNow(): Long {
        lastNowMillis = maxOf(lastNowMillis, clock.nowMillis())
        return lastNowMillis
    }

    private fun refilledBucket(sender: String, now: Long): Bucket {
        val bucket = buckets[sender]
        if (bucket != null) {
            bucket.creditMillis = minOf(capacityMillis, bucket.creditMillis + (now - bucket.updatedAtMillis))
            bucket.updatedAtMillis = now
            return bucket
        }
        if (buckets.size >= maxTrackedSenders) evict(now)
        return Bucket(capacityMillis, now).also { buckets[sender] = it }
    }

    private fun evict(now: Long) {
        buckets.values.removeIf { it.creditMillis + (now - it.updatedAtMillis) >= capacityMillis }
        val iterator = buckets.values.iterator()
        while (buckets.size >= maxTrackedSenders && iterator.hasNext()) {
            iterator.next()
            iterator.remove()
        }
    }

    private fun expireGrants(now: Long) {
        while (grants.isNotEmpty() && grants.peekFirst()[0] <= now - dutyWindowMillis) {
            grantedInWindowMillis -= grants.removeFirst()[1]
        }
    }
}

/** The outcome of [VibrationRateLimiter.tryAcquire]. */
public enum class VibrationDecision {
    /** Vibrate now. */
    VIBRATE,

    /** Do not vibrate: this sender has used up its burst; show the message without vibration. */
    SENDER_LIMIT,

    /** Do not vibrate: the phone has vibrated for its duty-cycle share of the window already. */
    DUTY_CYCLE_LIMIT,
}
