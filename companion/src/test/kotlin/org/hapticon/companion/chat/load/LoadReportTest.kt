package org.hapticon.companion.chat.load

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.jsonObject
import org.hapticon.core.io.Json
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

class LoadReportTest {
    private val tally = Tally(
        sent = 3_000, acknowledged = 3_000, failed = 0, delivered = 3_000, lost = 0, pending = 0, duplicates = 0, unexpected = 0, misrouted = 0,
        allMillis = LatencySummary(3_000, 2.5, 12.25, 40.0), steadyMillis = LatencySummary(3_000, 2.5, 12.25, 40.0), burstMillis = LatencySummary.EMPTY,
    )
    private val run = LoadResult(
        broker = "mosquitto", users = 1_000, connectSeconds = 12.34, connectionsHeld = 1_000, drops = 0, sendingSeconds = 60.0, tally = tally,
        receiptsSent = 3_000, receiptsReceived = 3_000, baselineMillis = LatencySummary(200, 0.75, 1.5, 2.0),
        memoryIdle = BrokerMemory(4_096, 4_096, null), memoryLoaded = BrokerMemory(20_480, 21_504, null),
        brokerCpuSeconds = 6.0, clientCpuSeconds = 30.0, machineBusy = 0.8125, cores = 2, loadAtStart = "1.00 / 2.00 / 3.00", loadAtEnd = "1.50 / 2.00 / 3.00",
    )

    @Test
    fun table_showsEveryFigureOfARunAndTheSkippedBroker() {
        val text = LoadReport.table(listOf(run), listOf(LoadSkip("embedded", "100 users: boom")), "SETUP")
        assertEquals(
            """
            |broker load: SETUP
            |  latency = send() called → receiver's listener, one monotonic clock in this process; baseline = 2 users, one message at a time, same broker, before the load
            |  CPU = CPU time used while sending by the broker process and by this process (all simulated clients), 100% = one core; and how busy the whole machine was
            |  embedded: SKIPPED: 100 users: boom
            |
            |  mosquitto, 1000 users: 1000/1000 connections held (0 drops), connected in 12.3 s; load 1.00 / 2.00 / 3.00 at start, 1.50 / 2.00 / 3.00 at end
            |    sent 3000 in 60.0 s: 50.0 messages/s (100.0 publishes/s with receipts; receipts 3000 sent, 3000 received)
            |    delivered 3000, lost 0, duplicated 0, failed at sender 0, still pending 0, unexpected 0, misrouted 0: every message accounted for
            |    latency ms       p50    2.50   p99   12.25   max    40.00   (3000)   (all messages)
            |    baseline ms      p50    0.75   p99    1.50   max     2.00   (200)
            |    broker memory    idle RSS 4.0 MiB (peak 4.0); loaded RSS 20.0 MiB (peak 21.0)
            |    CPU              broker 10%, clients 50% of a core; the machine 81% busy (all 2 cores, every process)
            |    target (p99 ≤ 50 ms, nothing lost, all connected): met
            """.trimMargin(),
            text,
        )
    }

    @Test
    fun json_sameBytesAsTheTreeBuiltByHandBefore() {
        // recorded/broker-load-report.json: these runs as LoadReport wrote them when it built a JsonObject tree by hand;
        // a heap figure, a figure that is not finite, a broker in this process and a skip whose reason needs escapes.
        val measured = run.copy(memoryLoaded = BrokerMemory(20_480, 21_504, 1_000), clientCpuSeconds = Double.NaN)
        val embedded = measured.copy(broker = "embedded", memoryIdle = BrokerMemory(0, 0, null), memoryLoaded = BrokerMemory(0, 0, null), connectionsHeld = 999)
        val recorded = LoadReportTest::class.java.getResource("/recorded/broker-load-report.json")!!.readText()
        assertEquals(recorded, LoadReport.json(listOf(measured, embedded), listOf(LoadSkip("embedded", "100 users: boom \"x\"")), "SETUP"))
    }

    @Test
    fun json_onePerRun_withNullForWhatWasNotMeasured() {
        val embedded = run.copy(
            broker = "embedded", memoryIdle = BrokerMemory(0, 0, null), memoryLoaded = BrokerMemory(0, 0, null),
            tally = tally.copy(lost = 1, delivered = 2_999), connectionsHeld = 999,
        )
        val json = Json.decode(LoadReport.json(listOf(run, embedded), emptyList(), "SETUP")) as JsonObject
        assertEquals(listOf("setup", "skipped", "runs"), json.keys.toList())
        assertEquals(JsonArray(emptyList()), json["skipped"])
        val runs = json["runs"] as JsonArray
        assertEquals(2, runs.size)
        val first = runs[0].jsonObject
        assertEquals(
            listOf(
                "broker", "users", "connectionsHeld", "drops", "connectSeconds", "sendingSeconds", "sent", "delivered", "lost", "duplicates",
                "failed", "pending", "unexpected", "misrouted", "allAccountedFor", "receiptsSent", "receiptsReceived", "messagesPerSecond",
                "publishesPerSecond", "latencyMillis", "steadyLatencyMillis", "burstLatencyMillis", "baselineLatencyMillis", "memoryIdle",
                "memoryLoaded", "brokerCpuSeconds", "clientCpuSeconds", "machineBusy", "cores", "loadAtStart", "loadAtEnd", "targetMet",
            ),
            first.keys.toList(),
        )
        assertEquals(JsonPrimitive(12.3), first["connectSeconds"])
        assertEquals(JsonPrimitive(50), first["messagesPerSecond"])
        assertEquals(
            JsonObject(mapOf("count" to JsonPrimitive(3_000), "p50" to JsonPrimitive(2.5), "p99" to JsonPrimitive(12.25), "max" to JsonPrimitive(40))),
            first["latencyMillis"],
        )
        assertEquals(JsonNull, first["burstLatencyMillis"])
        assertEquals(JsonObject(mapOf("rssKib" to JsonPrimitive(20_480), "peakRssKib" to JsonPrimitive(21_504), "heapUsedKib" to JsonNull)), first["memoryLoaded"])
        assertEquals(JsonPrimitive(0.813), first["machineBusy"])
        assertEquals(JsonPrimitive(true), first["targetMet"])
        val second = runs[1].jsonObject
        assertEquals(JsonNull, second["memoryLoaded"])
        assertEquals(JsonPrimitive(1), second["lost"])
        assertEquals(JsonPrimitive(false), second["allAccountedFor"])
        assertEquals(JsonPrimitive(false), second["targetMet"])
    }

    @Test
    fun targetMet_needsP99WithinTargetNothingLostAndEveryConnection() {
        assertTrue(run.targetMet)
        assertFalse(run.copy(tally = tally.copy(allMillis = LatencySummary(3_000, 2.5, 50.01, 90.0))).targetMet)
        assertTrue(run.copy(tally = tally.copy(allMillis = LatencySummary(3_000, 2.5, 50.0, 90.0))).targetMet)
        assertFalse(run.copy(connectionsHeld = 999).targetMet)
        assertFalse(run.copy(tally = tally.copy(duplicates = 1)).targetMet)
        assertFalse(run.copy(tally = tally.copy(failed = 1)).targetMet)
    }
}
