package org.hapticon.companion.chat.load

import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.atomic.AtomicInteger
import java.util.concurrent.atomic.AtomicLong

/**
 * Every message of a load run by id: when it was handed to the sender's client, whether the broker acknowledged it
 * (PUBACK), and each time it reached its recipient. All times come from one monotonic clock (`System.nanoTime` in
 * the one process that both sends and receives), so a latency is a difference of two readings of the same clock.
 * Thread-safe: senders, the client's acknowledgement threads and the receivers' delivery threads all write here.
 */
class DeliveryLedger {
    private class Entry(val recipient: String, val sentNanos: Long, val burst: Boolean) {
        @Volatile var acknowledged = false
        @Volatile var failed = false
        val arrivals = AtomicInteger()
        @Volatile var firstArrivalNanos = 0L
    }

    private val entries = ConcurrentHashMap<String, Entry>()
    private val unexpected = AtomicLong()
    private val misrouted = AtomicLong()

    /** [id] is about to be published to [recipient] at [nanos]; [burst] marks the messages of a synchronized burst. */
    fun sent(id: String, recipient: String, nanos: Long, burst: Boolean = false) {
        check(entries.putIfAbsent(id, Entry(recipient, nanos, burst)) == null) { "message $id sent twice" }
    }

    /** The broker acknowledged [id] (the publish returned). */
    fun acknowledged(id: String) {
        entries.getValue(id).acknowledged = true
    }

    /** Publishing [id] failed: the broker never acknowledged it, so the app's outbox would send it again. */
    fun failed(id: String) {
        entries.getValue(id).failed = true
    }

    /** [recipient]'s listener got [id] at [nanos]. A message nobody sent, or one that reached someone else, is counted apart. */
    fun received(id: String, recipient: String, nanos: Long) {
        val entry = entries[id]
        when {
            entry == null -> unexpected.incrementAndGet()
            entry.recipient != recipient -> misrouted.incrementAndGet()
            else -> if (entry.arrivals.incrementAndGet() == 1) entry.firstArrivalNanos = nanos
        }
    }

    /** How many messages are acknowledged and have not arrived yet: what a drain waits for. */
    fun outstanding(): Int = entries.values.count { it.acknowledged && it.arrivals.get() == 0 }

    /** Accounts for every message recorded so far. */
    fun tally(): Tally {
        val all = entries.values.toList()
        val steady = all.filter { !it.burst && it.arrivals.get() > 0 }.map { (it.firstArrivalNanos - it.sentNanos) / 1e6 }
        val burst = all.filter { it.burst && it.arrivals.get() > 0 }.map { (it.firstArrivalNanos - it.sentNanos) / 1e6 }
        return Tally(
            sent = all.size,
            acknowledged = all.count { it.acknowledged },
            failed = all.count { it.failed },
            delivered = all.count { it.arrivals.get() > 0 },
            lost = all.count { it.acknowledged && it.arrivals.get() == 0 },
            pending = all.count { !it.acknowledged && !it.failed && it.arrivals.get() == 0 },
            duplicates = all.sumOf { maxOf(0, it.arrivals.get() - 1) },
            unexpected = unexpected.get().toInt(),
            misrouted = misrouted.get().toInt(),
            allMillis = LatencySummary.of(steady + burst),
            steadyMillis = LatencySummary.of(steady),
            burstMillis = LatencySummary.of(burst),
        )
    }
}

/**
 * Where every message of a run went.
 *
 * @property sent messages handed to a sender's client.
 * @property acknowledged of those, how many the broker acknowledged (QoS 1 PUBACK).
 * @property failed publishes that threw: never acknowledged, so not counted lost (the app's outbox sends them again).
 * @property delivered messages that reached their recipient at least once.
 * @property lost acknowledged messages that never reached their recipient: the broker broke its promise.
 * @property pending messages neither acknowledged, nor failed, nor arrived: still in flight when counted.
 * @property duplicates arrivals beyond the first, summed over all messages.
 * @property unexpected arrivals of ids nobody sent in this run.
 * @property misrouted arrivals at a user the message was not addressed to.
 * @property allMillis send-to-receive latency of every delivered message (first arrival), ms.
 * @property steadyMillis send-to-receive latency of the messages sent at the human-ish rate, ms.
 * @property burstMillis the same for the messages of synchronized bursts.
 */
data class Tally(
    val sent: Int,
    val acknowledged: Int,
    val failed: Int,
    val delivered: Int,
    val lost: Int,
    val pending: Int,
    val duplicates: Int,
    val unexpected: Int,
    val misrouted: Int,
    val allMillis: LatencySummary,
    val steadyMillis: LatencySummary,
    val burstMillis: LatencySummary,
) {
    /**
     * True when every message id is accounted for: each one sent arrived exactly once at its recipient or failed
     * visibly at its sender, and nothing else arrived.
     */
    val allAccountedFor: Boolean
        get() = lost == 0 && pending == 0 && duplicates == 0 && unexpected == 0 && misrouted == 0
}

/**
 * Percentiles of a set of latencies, nearest-rank (the smallest value with at least p of the values at or below
 * it), so every figure is one that was measured.
 */
data class LatencySummary(val count: Int, val p50: Double, val p99: Double, val max: Double) {
    companion object {
        /** No values: the percentiles are NaN. */
        val EMPTY: LatencySummary = LatencySummary(0, Double.NaN, Double.NaN, Double.NaN)

        /** The summary of [values] (any order). */
        fun of(values: Collection<Double>): LatencySummary {
            if (values.isEmpty()) return EMPTY
            val sorted = values.sorted()
            return LatencySummary(sorted.size, nearestRank(sorted, 0.50), nearestRank(sorted, 0.99), sorted.last())
        }

        /** The nearest-rank [p] percentile of ascending [sorted]: the value at rank ceil(p·n). */
        fun nearestRank(sorted: List<Double>, p: Double): Double {
            require(sorted.isNotEmpty()) { "no values" }
            require(p > 0.0 && p <= 1.0) { "p must be in (0, 1], was $p" }
            val rank = Math.ceil(p * sorted.size).toInt().coerceIn(1, sorted.size)
            return sorted[rank - 1]
        }
    }
}
