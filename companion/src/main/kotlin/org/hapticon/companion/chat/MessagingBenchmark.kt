package org.hapticon.companion.chat

import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.io.SchemaJson
import org.hapticon.core.io.shortNumber
import org.hapticon.companion.cli.Console
import kotlinx.coroutines.runBlocking
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Decoded
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.mqtt.MqttMessenger
import java.nio.file.Files
import java.util.Locale
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

/**
 * `hapticon bench --messaging`: how fast messages are encoded and decoded, and how long one takes from
 * [MqttMessenger.send] to the receiver's listener through the embedded broker on loopback.
 */
object MessagingBenchmark {
    /** Codec throughput the messaging design asks for, in messages per second (encode + decode). */
    const val CODEC_TARGET_PER_SECOND: Double = 100_000.0

    /**
     * How much work to do.
     *
     * @property codecMessages messages encoded and decoded per measured run.
     * @property codecRuns measured runs (after as many warm-up runs); the median counts, and min and max are printed beside it.
     * @property latencyWarmup messages sent before latency is measured.
     * @property latencySamples messages whose latency is measured, one at a time.
     */
    class Config(val codecMessages: Int, val codecRuns: Int, val latencyWarmup: Int, val latencySamples: Int) {
        companion object {
            val FULL: Config = Config(codecMessages = 200_000, codecRuns = 5, latencyWarmup = 500, latencySamples = 2_000)
            val QUICK: Config = Config(codecMessages = 2_000, codecRuns = 2, latencyWarmup = 10, latencySamples = 50)
        }
    }

    /**
     * The figures.
     *
     * @property codecRates encode + decode throughput of each measured run, messages per second (at least one).
     * @property encodedBytes size of the benchmark message (text and the knock icon).
     * @property latencyP50Micros median send-to-listener latency in µs.
     * @property latencyP99Micros 99th percentile of that latency in µs.
     * @property latencySamples how many latencies were measured.
     * @property loadAverage the 1, 5 and 15 minute load averages when the codec runs started (`uptime`'s figures), or
     *   "unknown"; on a shared machine the codec's figure moves with it, so it is printed beside it.
     */
    class Result(
        val codecRates: List<Double>,
        val encodedBytes: Int,
        val latencyP50Micros: Double,
        val latencyP99Micros: Double,
        val latencySamples: Int,
        val loadAverage: String,
    ) {
        init {
            require(codecRates.isNotEmpty()) { "at least one codec run" }
        }

        private val sorted = codecRates.sorted()

        /** Median encode + decode throughput over the runs, messages per second; what the target is checked against. */
        val codecPerSecond: Double get() = sorted[sorted.size / 2]

        /** Slowest run, messages per second. */
        val codecMinPerSecond: Double get() = sorted.first()

        /** Fastest run, messages per second. */
        val codecMaxPerSecond: Double get() = sorted.last()

        /** Whether the codec meets [CODEC_TARGET_PER_SECOND]. */
        val codecTargetMet: Boolean get() = codecPerSecond >= CODEC_TARGET_PER_SECOND
    }

    /** Runs both measurements, reporting progress through [progress]. Blocks for a few seconds. */
    fun run(config: Config, progress: (String) -> Unit): Result {
        progress("messaging codec: ${config.codecRuns} runs of ${config.codecMessages} messages")
        val message = ChatMessage.compose("alice", "The quick brown fox jumps over the lazy dog", icon = HapticIcon.KNOCK)
        val encodedBytes = MessageCodec.encode(message).size
        val load = loadAverage()
        repeat(config.codecRuns) { codecRun(message, config.codecMessages) } // warm-up: let the JIT compile
        val rates = List(config.codecRuns) { config.codecMessages / codecRun(message, config.codecMessages) }
        progress("messaging latency: ${config.latencySamples} messages through the embedded broker")
        val latencies = latencyMicros(config).sorted()
        return Result(rates, encodedBytes, percentile(latencies, 0.50), percentile(latencies, 0.99), latencies.size, load)
    }

    /** The section `hapticon bench --messaging` prints. */
    fun table(result: Result): String = buildString {
        appendLine("messaging (one core for the codec; loopback through the embedded broker for latency)")
        appendLine(String.format(Locale.ROOT, "  encode + decode      %12.0f messages/s  (%d-byte message with text and knock icon)", result.codecPerSecond, result.encodedBytes))
        appendLine(
            String.format(
                Locale.ROOT, "  codec runs           min %.0f, median %.0f, max %.0f messages/s over %d runs; load %s at start",
                result.codecMinPerSecond, result.codecPerSecond, result.codecMaxPerSecond, result.codecRates.size, result.loadAverage,
            ),
        )
        appendLine(String.format(Locale.ROOT, "  send → receive p50   %12.1f µs", result.latencyP50Micros))
        appendLine(String.format(Locale.ROOT, "  send → receive p99   %12.1f µs  (%d messages, one at a time, QoS 1)", result.latencyP99Micros, result.latencySamples))
        append(String.format(Locale.ROOT, "  target: codec >= %.0f messages/s: %s", CODEC_TARGET_PER_SECOND, if (result.codecTargetMet) "met" else "NOT MET"))
    }

    /** The figures as one JSON object. */
    fun json(result: Result): String = SchemaJson.encodeElement(
        JsonObject(
            linkedMapOf(
                "codecMessagesPerSecond" to shortNumber(Math.round(result.codecPerSecond).toDouble()),
                "codecMinPerSecond" to shortNumber(Math.round(result.codecMinPerSecond).toDouble()),
                "codecMaxPerSecond" to shortNumber(Math.round(result.codecMaxPerSecond).toDouble()),
                "codecRuns" to shortNumber(result.codecRates.size),
                "loadAverage" to JsonPrimitive(result.loadAverage),
                "encodedBytes" to shortNumber(result.encodedBytes),
                "latencyP50Micros" to shortNumber(result.latencyP50Micros),
                "latencyP99Micros" to shortNumber(result.latencyP99Micros),
                "latencySamples" to shortNumber(result.latencySamples),
                "codecTargetMet" to JsonPrimitive(result.codecTargetMet),
            ),
        ),
        "  ",
    )

    /** Seconds to encode and decode [message] [count] times. */
    private fun codecRun(message: ChatMessage, count: Int): Double {
        val start = System.nanoTime()
        var accepted = 0
        repeat(count) {
            if (MessageCodec.decodeInbox(MessageCodec.encode(message)) is Decoded.Accepted) accepted++
        }
        val seconds = (System.nanoTime() - start) / 1e9
        check(accepted == count) { "only $accepted of $count messages decoded" }
        return seconds
    }

    private fun latencyMicros(config: Config): List<Double> {
        val store = Files.createTempDirectory("hapticon-bench-broker").toFile()
        try {
            DemoBroker(store, listOf("alice", "bob")).start().use { broker ->
                val arrivals = LinkedBlockingQueue<Long>()
                val alice = MqttMessenger(broker.settings("alice"))
                val bob = MqttMessenger(broker.settings("bob"))
                return runBlocking {
                    try {
                        alice.connect { }
                        bob.connect { event -> if (event is InboxEvent.MessageReceived) arrivals.put(System.nanoTime()) }
                        List(config.latencyWarmup + config.latencySamples) { i ->
                            val message = ChatMessage.compose("alice", "latency $i", icon = HapticIcon.KNOCK)
                            val start = System.nanoTime()
                            alice.send("bob", message)
                            val arrived = arrivals.poll(10, TimeUnit.SECONDS) ?: error("message $i did not arrive within 10 s")
                            (arrived - start) / 1e3
                        }.drop(config.latencyWarmup)
                    } finally {
                        alice.disconnect()
                        bob.disconnect()
                    }
                }
            }
        } finally {
            store.deleteRecursively()
        }
    }

    // As BenchCommand's --grain runs print it (1 / 5 / 15 minutes).
    private fun loadAverage(): String =
        runCatching { java.io.File("/proc/loadavg").readText().split(' ').take(3).joinToString(" / ") }.getOrDefault("unknown")

    private fun percentile(sorted: List<Double>, p: Double): Double = sorted[((sorted.size - 1) * p).let(Math::round).toInt()]
}

/** `hapticon bench --messaging [--quick] [--json]`: the [MessagingBenchmark] figures to stdout, progress to stderr. */
fun runMessagingBench(quick: Boolean, json: Boolean, console: Console) {
    val config = if (quick) MessagingBenchmark.Config.QUICK else MessagingBenchmark.Config.FULL
    val result = MessagingBenchmark.run(config) { step -> console.err.println("bench: $step") }
    console.out.println(if (json) MessagingBenchmark.json(result) else MessagingBenchmark.table(result))
}
