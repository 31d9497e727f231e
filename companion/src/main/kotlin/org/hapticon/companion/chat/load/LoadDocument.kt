package org.hapticon.companion.chat.load

import kotlinx.serialization.Serializable
import org.hapticon.core.io.ShortDouble

/**
 * What `hapticon bench --broker-load --json` prints ([LoadReport.json]): the set-up, the brokers skipped and one entry
 * per broker and number of users. A figure that was not measured is `null` (a latency without messages, the memory of
 * a broker in this process, a non-finite time); numbers are spelled short ([ShortDouble]).
 */
@Serializable
internal class LoadDocument(val setup: String, val skipped: List<SkipDocument>, val runs: List<LoadRunDocument>)

@Serializable
internal class SkipDocument(val broker: String, val reason: String)

@Serializable
internal class LoadRunDocument(
    val broker: String,
    val users: Int,
    val connectionsHeld: Int,
    val drops: Int,
    @Serializable(with = ShortDouble::class) val connectSeconds: Double?,
    @Serializable(with = ShortDouble::class) val sendingSeconds: Double?,
    val sent: Int,
    val delivered: Int,
    val lost: Int,
    val duplicates: Int,
    val failed: Int,
    val pending: Int,
    val unexpected: Int,
    val misrouted: Int,
    val allAccountedFor: Boolean,
    val receiptsSent: Int,
    val receiptsReceived: Int,
    @Serializable(with = ShortDouble::class) val messagesPerSecond: Double?,
    @Serializable(with = ShortDouble::class) val publishesPerSecond: Double?,
    val latencyMillis: LatencyDocument?,
    val steadyLatencyMillis: LatencyDocument?,
    val burstLatencyMillis: LatencyDocument?,
    val baselineLatencyMillis: LatencyDocument?,
    val memoryIdle: MemoryDocument?,
    val memoryLoaded: MemoryDocument?,
    @Serializable(with = ShortDouble::class) val brokerCpuSeconds: Double?,
    @Serializable(with = ShortDouble::class) val clientCpuSeconds: Double?,
    @Serializable(with = ShortDouble::class) val machineBusy: Double?,
    val cores: Int,
    val loadAtStart: String,
    val loadAtEnd: String,
    val targetMet: Boolean,
)

/** A [LatencySummary] with messages in it, in ms to the µs. */
@Serializable
internal class LatencyDocument(
    val count: Int,
    @Serializable(with = ShortDouble::class) val p50: Double?,
    @Serializable(with = ShortDouble::class) val p99: Double?,
    @Serializable(with = ShortDouble::class) val max: Double?,
)

/** A measured [BrokerMemory]. */
@Serializable
internal class MemoryDocument(val rssKib: Long, val peakRssKib: Long, val heapUsedKib: Long?)
