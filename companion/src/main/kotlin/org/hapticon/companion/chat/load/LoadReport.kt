package org.hapticon.companion.chat.load

import org.hapticon.core.io.SchemaJson
import java.util.Locale

/**
 * One load run's figures.
 *
 * @property connectSeconds how long the [users] took to connect (logins a few at a time).
 * @property connectionsHeld users still connected after the run.
 * @property drops connections that left the connected state during the run (each reconnects on its own).
 * @property sendingSeconds how long the users sent.
 * @property baselineMillis one message at a time between two users on the same broker, before the load.
 * @property memoryIdle the broker's memory before the users connected.
 * @property memoryLoaded the broker's memory when sending stopped.
 * @property brokerCpuSeconds CPU time the broker process used while the users sent.
 * @property clientCpuSeconds CPU time this process (every simulated client) used meanwhile.
 * @property machineBusy the fraction of all [cores]' time the whole machine was busy meanwhile (every process, ours and others').
 */
data class LoadResult(
    val broker: String,
    val users: Int,
    val connectSeconds: Double,
    val connectionsHeld: Int,
    val drops: Int,
    val sendingSeconds: Double,
    val tally: Tally,
    val receiptsSent: Int,
    val receiptsReceived: Int,
    val baselineMillis: LatencySummary,
    val memoryIdle: BrokerMemory,
    val memoryLoaded: BrokerMemory,
    val brokerCpuSeconds: Double,
    val clientCpuSeconds: Double,
    val machineBusy: Double,
    val cores: Int,
    val loadAtStart: String,
    val loadAtEnd: String,
) {
    /** Chat messages delivered per second of sending (receipts not counted). */
    val messagesPerSecond: Double get() = tally.delivered / sendingSeconds

    /** Every MQTT publish delivered per second: messages and receipts. */
    val publishesPerSecond: Double get() = (tally.delivered + receiptsReceived) / sendingSeconds

    /** Latency of every message, steady and burst together: what the target is checked against. */
    val allMillis: LatencySummary get() = tally.allMillis

    /** p99 ≤ [TARGET_P99_MILLIS], nothing lost, every connection held. */
    val targetMet: Boolean get() = tally.allAccountedFor && tally.failed == 0 && connectionsHeld == users && allMillis.p99 <= TARGET_P99_MILLIS

    companion object {
        /** The target: 1,000 users with p99 delivery ≤ 50 ms and nothing lost. */
        const val TARGET_P99_MILLIS: Double = 50.0
    }
}

/** A broker the run could not use, and why. */
data class LoadSkip(val broker: String, val reason: String)

/** The table and JSON of `hapticon bench --broker-load`. */
object LoadReport {
    /** The text table: one block per run, what was measured said once at the top. */
    fun table(runs: List<LoadResult>, skips: List<LoadSkip>, setup: String): String = buildString {
        appendLine("broker load: $setup")
        appendLine("  latency = send() called → receiver's listener, one monotonic clock in this process; baseline = 2 users, one message at a time, same broker, before the load")
        appendLine("  CPU = CPU time used while sending by the broker process and by this process (all simulated clients), 100% = one core; and how busy the whole machine was")
        for (skip in skips) appendLine("  ${skip.broker}: SKIPPED: ${skip.reason}")
        for (r in runs) {
            val t = r.tally
            appendLine()
            appendLine(String.format(Locale.ROOT, "  %s, %d users: %d/%d connections held (%d drops), connected in %.1f s; load %s at start, %s at end", r.broker, r.users, r.connectionsHeld, r.users, r.drops, r.connectSeconds, r.loadAtStart, r.loadAtEnd))
            appendLine(String.format(Locale.ROOT, "    sent %d in %.1f s: %.1f messages/s (%.1f publishes/s with receipts; receipts %d sent, %d received)", t.sent, r.sendingSeconds, r.messagesPerSecond, r.publishesPerSecond, r.receiptsSent, r.receiptsReceived))
            appendLine(String.format(Locale.ROOT, "    delivered %d, lost %d, duplicated %d, failed at sender %d, still pending %d, unexpected %d, misrouted %d: %s", t.delivered, t.lost, t.duplicates, t.failed, t.pending, t.unexpected, t.misrouted, if (t.allAccountedFor) "every message accounted for" else "NOT all accounted for"))
            appendLine("    latency ms       " + latencyLine(r.allMillis) + "   (all messages)")
            if (t.burstMillis.count > 0) {
                appendLine("      steady         " + latencyLine(t.steadyMillis))
                appendLine("      bursts         " + latencyLine(t.burstMillis))
            }
            appendLine("    baseline ms      " + latencyLine(r.baselineMillis))
            appendLine("    broker memory    idle ${memoryLine(r.memoryIdle)}; loaded ${memoryLine(r.memoryLoaded)}")
            appendLine(
                String.format(
                    Locale.ROOT, "    CPU              broker %.0f%%, clients %.0f%% of a core; the machine %.0f%% busy (all %d cores, every process)",
                    100 * r.brokerCpuSeconds / r.sendingSeconds, 100 * r.clientCpuSeconds / r.sendingSeconds, 100 * r.machineBusy, r.cores,
                ),
            )
            append(String.format(Locale.ROOT, "    target (p99 ≤ %.0f ms, nothing lost, all connected): %s", LoadResult.TARGET_P99_MILLIS, if (r.targetMet) "met" else "NOT MET"))
            appendLine()
        }
    }.trimEnd()

    /** The same figures as one JSON object ([LoadDocument]): `setup`, `skipped` and one `runs` entry per broker and N. */
    fun json(runs: List<LoadResult>, skips: List<LoadSkip>, setup: String): String = SchemaJson.encode(
        LoadDocument.serializer(),
        LoadDocument(setup, skips.map { SkipDocument(it.broker, it.reason) }, runs.map(::runDocument)),
        "  ",
    )

    private fun runDocument(r: LoadResult): LoadRunDocument {
        val t = r.tally
        return LoadRunDocument(
            broker = r.broker, users = r.users, connectionsHeld = r.connectionsHeld, drops = r.drops,
            connectSeconds = rounded(r.connectSeconds, 10), sendingSeconds = rounded(r.sendingSeconds, 10),
            sent = t.sent, delivered = t.delivered, lost = t.lost, duplicates = t.duplicates, failed = t.failed, pending = t.pending,
            unexpected = t.unexpected, misrouted = t.misrouted, allAccountedFor = t.allAccountedFor,
            receiptsSent = r.receiptsSent, receiptsReceived = r.receiptsReceived,
            messagesPerSecond = rounded(r.messagesPerSecond, 10), publishesPerSecond = rounded(r.publishesPerSecond, 10),
            latencyMillis = latencyDocument(r.allMillis), steadyLatencyMillis = latencyDocument(t.steadyMillis),
            burstLatencyMillis = latencyDocument(t.burstMillis), baselineLatencyMillis = latencyDocument(r.baselineMillis),
            memoryIdle = memoryDocument(r.memoryIdle), memoryLoaded = memoryDocument(r.memoryLoaded),
            brokerCpuSeconds = rounded(r.brokerCpuSeconds, 100), clientCpuSeconds = rounded(r.clientCpuSeconds, 100),
            machineBusy = rounded(r.machineBusy, 1000),
            cores = r.cores, loadAtStart = r.loadAtStart, loadAtEnd = r.loadAtEnd, targetMet = r.targetMet,
        )
    }

    private fun latencyLine(l: LatencySummary): String =
        if (l.count == 0) "none" else String.format(Locale.ROOT, "p50 %7.2f   p99 %7.2f   max %8.2f   (%d)", l.p50, l.p99, l.max, l.count)

    private fun memoryLine(m: BrokerMemory): String {
        if (m.rssKib == 0L) return "not measured (broker in this process)"
        val heap = m.heapUsedKib?.let { String.format(Locale.ROOT, ", heap after GC %.1f MiB", it / 1024.0) } ?: ""
        return String.format(Locale.ROOT, "RSS %.1f MiB (peak %.1f)%s", m.rssKib / 1024.0, m.peakRssKib / 1024.0, heap)
    }

    private fun latencyDocument(l: LatencySummary): LatencyDocument? =
        if (l.count == 0) null else LatencyDocument(l.count, rounded(l.p50, 1000), rounded(l.p99, 1000), rounded(l.max, 1000))

    private fun memoryDocument(m: BrokerMemory): MemoryDocument? = if (m.rssKib == 0L) null else MemoryDocument(m.rssKib, m.peakRssKib, m.heapUsedKib)

    /** [value] to 1/[scale], or null (written `null`) when it is not finite. */
    private fun rounded(value: Double, scale: Int): Double? = if (value.isFinite()) Math.round(value * scale).toDouble() / scale else null
}
