package org.hapticon.companion

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.bench.BenchConfig
import org.hapticon.companion.bench.BenchReport
import org.hapticon.companion.bench.CpuLatencyRequest
import org.hapticon.companion.bench.Renice
import org.hapticon.companion.bench.Benchmark
import org.hapticon.companion.bench.GrainLatency
import org.hapticon.companion.chat.load.BROKER_LOAD_OPTIONS
import org.hapticon.companion.chat.load.runBrokerLoadBench
import org.hapticon.companion.chat.runMessagingBench
import org.hapticon.companion.study.AnalysisBench
import java.util.concurrent.atomic.AtomicReference

/**
 * `hapticon bench [--json] [--quick] [--messaging | --analysis | --grain [--runs N] [--interval-us N] [--spin-us N]
 * [--cpu-latency-us N] [--reader-nice N] | --broker-load [options of runBrokerLoadBench]]`:
 * measurements to stdout, progress to stderr.
 */
fun runBench(args: List<String>, console: Console) {
    val arguments = Arguments.parse(
        "bench", args,
        valueOptions = GRAIN_OPTIONS.toSet() + BROKER_LOAD_OPTIONS,
        flagOptions = setOf("json", "quick", "messaging", "analysis", "grain", "broker-load"),
    )
    arguments.requireNoPositionals()
    val loadOptions = BROKER_LOAD_OPTIONS.filter { arguments.value(it) != null }
    if (arguments.flag("broker-load")) {
        if (listOf("quick", "messaging", "analysis", "grain").any(arguments::flag)) throw UsageException("bench --broker-load takes its own options; leave out --quick, --messaging, --analysis and --grain")
        return runBrokerLoadBench(arguments, console)
    }
    if (loadOptions.isNotEmpty()) throw UsageException("--${loadOptions[0]} goes with --broker-load")
    val grainOptions = GRAIN_OPTIONS.filter { arguments.value(it) != null }
    if (!arguments.flag("grain") && grainOptions.isNotEmpty()) throw UsageException("--${grainOptions[0]} goes with --grain")
    if (arguments.flag("grain")) return runGrainBench(arguments, console)
    if (arguments.flag("analysis")) {
        if (arguments.flag("json")) throw UsageException("bench --analysis prints a table only; leave out --json")
        val config = if (arguments.flag("quick")) AnalysisBench.Config.QUICK else AnalysisBench.Config.FULL
        val sizes = AnalysisBench(config) { console.err.println("bench: $it") }.run()
        return console.out.println(AnalysisBench.table(sizes))
    }
    if (arguments.flag("messaging")) return runMessagingBench(arguments.flag("quick"), arguments.flag("json"), console)
    val config = if (arguments.flag("quick")) BenchConfig.QUICK else BenchConfig.FULL
    val result = Benchmark(config) { step -> console.err.println("bench: $step") }.run()
    console.out.println(if (arguments.flag("json")) BenchReport.json(result) else BenchReport.table(result))
}

/**
 * `hapticon bench --grain`: only the fake-port sample-to-grain latency through `GrainEngine`, [GrainLatency]
 * run `--runs` times (default 3) with the `uptime` load average printed beside each run, since the worst case
 * depends on what else the machine runs. `--interval-us` paces the samples (1000 = the board's 1 kHz; default
 * 0, back to back), `--spin-us` keeps the reader spinning that long after each sample before it blocks.
 * `--cpu-latency-us N` holds a Linux PM QoS CPU latency request of N µs for all runs ([CpuLatencyRequest], root
 * only: refused, one line says so and the runs go on); `--reader-nice N` renices each run's reader thread to N
 * before its first read ([Renice], through the `renice` command: Java has no setpriority). Each run's line
 * says what was granted, so one line per run holds everything a quiet-machine re-run needs.
 */
private fun runGrainBench(arguments: Arguments, console: Console) {
    if (arguments.flag("json") || arguments.flag("messaging") || arguments.flag("analysis")) {
        throw UsageException("bench --grain prints its lines only; leave out --json, --messaging and --analysis")
    }
    val runs = arguments.int("runs", 3)
    val interval = arguments.int("interval-us", 0)
    val spin = arguments.int("spin-us", 0)
    if (runs !in 1..100) throw UsageException("--runs must be in 1..100, got $runs")
    if (interval !in 0..100_000) throw UsageException("--interval-us must be in 0..100000, got $interval")
    if (spin !in 0..100_000) throw UsageException("--spin-us must be in 0..100000, got $spin")
    val cpuLatency = arguments.value("cpu-latency-us")?.let { arguments.int("cpu-latency-us", 0) }
    if (cpuLatency != null && cpuLatency !in 0..100_000) throw UsageException("--cpu-latency-us must be in 0..100000, got $cpuLatency")
    val nice = arguments.value("reader-nice")?.let { arguments.int("reader-nice", 0) }
    if (nice != null && nice !in -20..19) throw UsageException("--reader-nice must be in -20..19, got $nice")
    val quick = arguments.flag("quick")
    val config = if (quick) BenchConfig.QUICK else BenchConfig.FULL
    // Paced runs take a period per sample: 20,000 measured after 5,000 warm-up at 1 kHz is 25 s a run.
    val samples = if (interval > 0 && !quick) PACED_SAMPLES else config.latencySamples
    val warmup = if (interval > 0 && !quick) PACED_WARMUP_SAMPLES else config.latencyWarmupSamples
    console.out.println("grain latency through GrainEngine, µs; samples ${if (interval > 0) "every $interval µs" else "back to back"}, reader spin $spin µs after each sample")
    val request = cpuLatency?.let { CpuLatencyRequest.open(it) }
    request?.let { console.out.println(it.outcome) }
    try {
        repeat(runs) { run ->
            val load = loadAverage()
            console.err.println("bench: grain latency run ${run + 1} of $runs")
            val niceOutcome = AtomicReference<String>()
            val setup: (Long) -> Unit = if (nice == null) { _ -> } else { tid ->
                niceOutcome.set(if (tid < 0) "reader nice $nice refused (no thread id)" else Renice.apply(tid, nice))
            }
            val result = GrainLatency(samples, warmup, GrainLatency.Route.ENGINE, intervalMicros = interval, readerSpinMicros = spin, readerSetup = setup).run()
            val conditions = listOfNotNull(
                "load $load",
                request?.let { if (it.granted) "cpu latency ${it.micros} µs held" else "cpu latency refused" },
                niceOutcome.get(),
            )
            console.out.println("run ${run + 1} (${conditions.joinToString("; ")}): " + BenchReport.grainLine(result))
        }
    } finally {
        request?.close()
    }
}

private val GRAIN_OPTIONS = listOf("runs", "interval-us", "spin-us", "cpu-latency-us", "reader-nice")

private const val PACED_SAMPLES = 20_000
private const val PACED_WARMUP_SAMPLES = 5_000

/** The 1, 5 and 15 minute load averages as `uptime` prints them, or "unknown" off Linux. */
private fun loadAverage(): String =
    runCatching { java.io.File("/proc/loadavg").readText().split(' ').take(3).joinToString(" / ") }.getOrDefault("unknown")
