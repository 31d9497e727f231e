package org.hapticon.companion.chat.load

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import java.io.File
import java.io.IOException
import java.nio.file.Files

/** The value options of `bench --broker-load`. */
val BROKER_LOAD_OPTIONS: Set<String> = setOf("users", "duration", "interval", "burst", "broker", "broker-heap-mb", "mosquitto-conf")

/**
 * `hapticon bench --broker-load [--users N[,N…]] [--duration S] [--interval MIN-MAX] [--burst K]
 * [--broker embedded|mosquitto|both] [--broker-heap-mb M] [--mosquitto-conf FILE] [--json]`: a [BrokerLoad] run per
 * broker and N, the figures to stdout ([LoadReport]), progress to stderr. Defaults: 100 and 1,000 users, 60 s, one
 * message every 10–30 s per user, no burst, both brokers. A missing Mosquitto is one line, not a failure.
 */
fun runBrokerLoadBench(arguments: Arguments, console: Console) {
    val users = (arguments.value("users") ?: "100,1000").split(',').map { text ->
        text.trim().toIntOrNull()?.takeIf { it in 2..100_000 } ?: throw UsageException("--users takes numbers in 2..100000 separated by commas, got '$text'")
    }
    val duration = arguments.int("duration", 60)
    if (duration !in 1..3_600) throw UsageException("--duration must be in 1..3600 seconds, got $duration")
    val interval = arguments.value("interval") ?: "10-30"
    val bounds = Regex("(\\d+)-(\\d+)").matchEntire(interval)?.destructured?.let { (a, b) -> a.toLong() to b.toLong() }
    if (bounds == null || bounds.first < 1 || bounds.second < bounds.first || bounds.second > 3_600) {
        throw UsageException("--interval takes MIN-MAX seconds between one user's messages, 1 <= MIN <= MAX <= 3600, got '$interval'")
    }
    val burst = arguments.int("burst", 0)
    if (burst !in 0..1_000) throw UsageException("--burst must be in 0..1000, got $burst")
    val brokers = when (val which = arguments.value("broker") ?: "both") {
        "embedded" -> listOf("embedded")
        "mosquitto" -> listOf("mosquitto")
        "both" -> listOf("embedded", "mosquitto")
        else -> throw UsageException("--broker takes embedded, mosquitto or both, got '$which'")
    }
    val heap = arguments.value("broker-heap-mb")?.let { arguments.int("broker-heap-mb", 0) }
    if (heap != null && heap !in 64..65_536) throw UsageException("--broker-heap-mb must be in 64..65536, got $heap")
    val conf = arguments.value("mosquitto-conf")?.let(::File) ?: MosquittoBroker.shippedConf()

    val skips = ArrayList<LoadSkip>()
    val starters = LinkedHashMap<String, (File, File) -> LoadBroker>()
    if ("embedded" in brokers) starters["embedded"] = { dir, passwd -> ChildEmbeddedBroker.start(dir, passwd, heap) }
    if ("mosquitto" in brokers) {
        val reason = MosquittoBroker.unavailable() ?: if (conf == null || !conf.isFile) "the shipped companion/mosquitto/mosquitto.conf was not found; give it with --mosquitto-conf FILE" else null
        if (reason != null) {
            skips += LoadSkip("mosquitto", reason)
            console.err.println("bench: mosquitto skipped: $reason")
        } else {
            starters["mosquitto"] = { dir, passwd -> MosquittoBroker.start(dir, conf!!, passwd) }
        }
    }
    val setup = "one message (text + knock icon, QoS 1) per user every ${bounds.first}-${bounds.second} s to a random peer, each answered by a delivered receipt" +
        (if (burst > 0) "; $burst messages per user at once at 1/3 and 2/3 of the run" else "") +
        "; ${duration} s per run; auth + shipped ACL; each user its own client id USER:DEVICE; all clients in this JVM on HiveMQ's shared event loops; " +
        "${Runtime.getRuntime().availableProcessors()} cores"
    val runs = ArrayList<LoadResult>()
    for (n in users) {
        for ((name, start) in starters) {
            val dir = Files.createTempDirectory("hapticon-broker-load").toFile()
            try {
                val load = BrokerLoad(n, duration * 1_000L, bounds.first * 1_000, bounds.second * 1_000, burst)
                runs += load.run(dir, start) { console.err.println("bench: $it") }
            } catch (e: IOException) {
                skips += LoadSkip(name, "$n users: ${e.message}")
                console.err.println("bench: $name with $n users failed: ${e.message}")
            } finally {
                dir.deleteRecursively()
            }
        }
    }
    console.out.println(if (arguments.flag("json")) LoadReport.json(runs, skips, setup) else LoadReport.table(runs, skips, setup))
}
