package org.hapticon.companion.chat

import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.booleanOrNull
import kotlinx.serialization.json.double
import kotlinx.serialization.json.jsonPrimitive
import org.hapticon.companion.cli
import org.hapticon.core.io.Json
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

class MessagingBenchmarkTest {
    @Test
    fun benchMessagingQuickJson_measuresBothPartsAndPrintsOneObject() {
        // One run only: each starts and stops a broker, which takes seconds.
        val result = cli("bench", "--messaging", "--quick", "--json")
        assertEquals(result.toString(), 0, result.exitCode)
        assertEquals(
            listOf("bench: messaging codec: 2 runs of 2000 messages", "bench: messaging latency: 50 messages through the embedded broker"),
            result.stderrLines,
        )
        val json = Json.decode(result.stdout) as JsonObject
        assertEquals(
            listOf(
                "codecMessagesPerSecond", "codecMinPerSecond", "codecMaxPerSecond", "codecRuns", "loadAverage",
                "encodedBytes", "latencyP50Micros", "latencyP99Micros", "latencySamples", "codecTargetMet",
            ),
            json.keys.toList(),
        )
        assertEquals(JsonPrimitive(2), json["codecRuns"])
        val min = json["codecMinPerSecond"]!!.jsonPrimitive.double
        val median = json["codecMessagesPerSecond"]!!.jsonPrimitive.double
        val max = json["codecMaxPerSecond"]!!.jsonPrimitive.double
        assertTrue("min $min <= median $median <= max $max", min > 0.0 && min <= median && median <= max)
        // /proc/loadavg's first three figures, as uptime prints them (this machine is Linux).
        assertTrue(json["loadAverage"].toString(), Regex("\"\\d+\\.\\d\\d / \\d+\\.\\d\\d / \\d+\\.\\d\\d\"").matches(json["loadAverage"].toString()))
        // The benchmark message: 43 characters of text and the knock icon, as the codec writes it.
        assertEquals(JsonPrimitive(346), json["encodedBytes"])
        assertEquals(JsonPrimitive(50), json["latencySamples"])
        val p50 = json["latencyP50Micros"]!!.jsonPrimitive.double
        val p99 = json["latencyP99Micros"]!!.jsonPrimitive.double
        assertTrue("p50 $p50 <= p99 $p99", p50 > 0.0 && p50 <= p99)
        assertTrue(json["codecTargetMet"].let { it is JsonPrimitive && !it.isString && it.booleanOrNull != null })
    }

    @Test
    fun table_result_showsEveryFigureAndTheVerdict() {
        val result = MessagingBenchmark.Result(
            codecRates = listOf(251_094.4, 198_000.2, 262_500.7, 240_100.0, 255_300.0), encodedBytes = 346,
            latencyP50Micros = 429.14, latencyP99Micros = 3776.1, latencySamples = 2_000, loadAverage = "0.52 / 1.10 / 2.37",
        )
        assertEquals(
            """
            |messaging (one core for the codec; loopback through the embedded broker for latency)
            |  encode + decode            251094 messages/s  (346-byte message with text and knock icon)
            |  codec runs           min 198000, median 251094, max 262501 messages/s over 5 runs; load 0.52 / 1.10 / 2.37 at start
            |  send → receive p50          429.1 µs
            |  send → receive p99         3776.1 µs  (2000 messages, one at a time, QoS 1)
            |  target: codec >= 100000 messages/s: met
            """.trimMargin(),
            MessagingBenchmark.table(result),
        )
        // The median decides, not the fastest run.
        assertEquals(false, MessagingBenchmark.Result(listOf(99_999.0, 150_000.0, 90_000.0), 346, 1.0, 2.0, 1, "unknown").codecTargetMet)
        assertEquals(true, MessagingBenchmark.Result(listOf(100_000.0), 346, 1.0, 2.0, 1, "unknown").codecTargetMet)
    }
}
