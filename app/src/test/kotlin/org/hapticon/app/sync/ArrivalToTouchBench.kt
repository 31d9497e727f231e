package org.hapticon.app.sync

import android.content.Context
import androidx.test.core.app.ApplicationProvider
import java.io.File
import java.util.Locale
import org.hapticon.app.data.TestAndroidKeyStore
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Decoded
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.Identity
import org.hapticon.testing.TestKeyPins
import org.hapticon.messaging.e2e.Opened
import org.junit.After
import org.junit.Assume.assumeTrue
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config

/**
 * Arrival to touch, measured (docs/performance.md, "Arrival to touch"): a benchmark, not a test. It runs only when
 * `HAPTICON_BENCH_ARRIVAL` holds the number of messages, and prints the table without asserting a time:
 *
 *     HAPTICON_BENCH_ARRIVAL=10000 ./build test :app --tests ArrivalToTouchBench
 *
 * bob sends a text with the knock icon, sealed end to end, through the embedded broker; alice's phone ([ArrivalRig]:
 * the app's receive path) decodes it, stores it in Room, sends a delivered receipt, posts the notification and
 * hands the icon's vibration to the platform; the next message goes once bob has the felt receipt. Per message the
 * stages' times are kept ([ArrivalStage]); after each, the same run times the baseline: decoding alone (opening a
 * payload sealed the same way and [MessageCodec.decodeInbox], what the messenger does before its listener).
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35], shadows = [HandoffVibrator::class])
class ArrivalToTouchBench {
    @get:Rule
    val temp = TemporaryFolder()

    private val count = System.getenv(ENV)?.toIntOrNull()

    @Before
    fun setUp() {
        assumeTrue("$ENV=N runs the arrival-to-touch benchmark over N messages", count != null && count > 0)
        TestAndroidKeyStore.install()
    }

    @After
    fun tearDown() = TestAndroidKeyStore.uninstall()

    @Test
    fun arrivalToTouch() {
        val n = count!!
        val warmUp = minOf(WARM_UP, n)
        val loadBefore = loadAverage()
        val started = System.nanoTime()
        val decode = DecodeBaseline()
        ArrivalRig(ApplicationProvider.getApplicationContext<Context>(), temp.newFolder("arrival")).use { rig ->
            repeat(warmUp) { rig.deliver(rig.knock("warm-up $it")); decode.time(rig.knock("warm-up $it")) }
            val arrivals = ArrayList<Arrival>(n)
            val baseline = DoubleArray(n)
            for (i in 0 until n) {
                arrivals += rig.deliver(rig.knock("message $i"))
                baseline[i] = decode.time(rig.knock("message $i"))
            }
            check(rig.strays.isEmpty()) { "vibrations or notifications outside a message: ${rig.strays.take(5)}" }
            val report = report(n, warmUp, arrivals, baseline, loadBefore, loadAverage(), (System.nanoTime() - started) / 1e9)
            // Indented, so the build shows it as it runs (and it is in out/app/test.log).
            println(report.lines().joinToString("\n") { "    $it" })
            File(System.getProperty("user.dir"), "../out/app").takeIf { it.isDirectory }?.let { File(it, "bench-arrival.txt").writeText(report + "\n") }
        }
    }

    /** Opening and decoding a sealed payload alone, as the messenger does before its listener; µs are returned in ms. */
    private class DecodeBaseline {
        private val alice = EndToEnd(Identity.generate("alice"), TestKeyPins())
        private val bob = EndToEnd(Identity.generate("bob"), TestKeyPins()).also { it.learn("alice", alice.identity.bundle.encoded) }

        fun time(message: ChatMessage): Double {
            val sealed = bob.seal("alice", MessageCodec.encode(message))
            val start = System.nanoTime()
            val opened = alice.open("bob", sealed) as Opened.Plain
            val decoded = MessageCodec.decodeInbox(opened.plaintext)
            val end = System.nanoTime()
            check((decoded as Decoded.Accepted).value == message)
            return (end - start) / 1e6
        }
    }

    private fun report(
        n: Int, warmUp: Int, arrivals: List<Arrival>, baseline: DoubleArray, loadBefore: String, loadAfter: String, seconds: Double,
    ): String = buildString {
        fun line(format: String, vararg args: Any?) = append(String.format(Locale.ROOT, format, *args)).append('\n')
        line("arrival to touch: %,d messages (after %,d unmeasured), one at a time, bob -> alice, sealed end to end,", n, warmUp)
        line("through the embedded broker (child JVM); alice's receive path under Robolectric (SDK 35), Room on a SQLite file")
        line("load average before %s, after %s (1/5/15 min); %d cores; %.0f s", loadBefore, loadAfter, Runtime.getRuntime().availableProcessors(), seconds)
        line("")
        line("%-58s %8s %8s %8s %8s %7s", "stage, ms", "p50", "p99", "max", "mean", "share")
        val total = arrivals.map { it.millis(ArrivalStage.SENT, ArrivalStage.VIBRATED) }
        val totalMean = total.average()
        for ((from, to) in ArrivalStage.entries.zipWithNext()) {
            val times = arrivals.map { it.millis(from, to) }
            val mean = times.average()
            line("  %-56s %8.2f %8.2f %8.2f %8.2f %6.0f%%", "-> " + to.label, percentile(times, 50.0), percentile(times, 99.0), times.max(), mean, 100 * mean / totalMean)
        }
        val acked = arrivals.map { (it.receiptAcked - it.at[ArrivalStage.STORED.ordinal]) / 1e6 }
        line("  %-56s %8.2f %8.2f %8.2f %8.2f", "(beside: stored -> delivered receipt acknowledged)", percentile(acked, 50.0), percentile(acked, 99.0), acked.max(), acked.average())
        line("  %-56s %8.2f %8.2f %8.2f %8.2f", "arrival to touch (send() to the vibration)", percentile(total, 50.0), percentile(total, 99.0), total.max(), totalMean)
        val b = baseline.toList()
        line("  %-56s %8.2f %8.2f %8.2f %8.2f", "baseline, same run: decode alone (open + decodeInbox)", percentile(b, 50.0), percentile(b, 99.0), b.max(), b.average())
        line("")
        line("p50 / p99 nearest rank; a stage's p99 and the total's come from different messages, so they do not add up.")
        line("The first stage includes bob sealing the message and the broker's round trip to alice's client.")
        val p99 = percentile(total, 99.0)
        line("target: arrival to touch p99 <= %.0f ms: measured %.2f ms, %s", TARGET_MILLIS, p99, if (p99 <= TARGET_MILLIS) "met" else "NOT MET")
    }.trimEnd()

    private fun percentile(values: List<Double>, p: Double): Double {
        val sorted = values.sorted()
        val rank = kotlin.math.ceil(p / 100 * sorted.size).toInt().coerceIn(1, sorted.size)
        return sorted[rank - 1]
    }

    private fun loadAverage(): String =
        runCatching { File("/proc/loadavg").readText().split(' ').take(3).joinToString(" ") }.getOrDefault("unknown")

    private companion object {
        const val ENV = "HAPTICON_BENCH_ARRIVAL"
        const val WARM_UP = 500
        const val TARGET_MILLIS = 20.0
    }
}
