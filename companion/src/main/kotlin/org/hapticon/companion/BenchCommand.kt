package org.hapticon.companion

import org.hapticon.companion.bench.BenchConfig
import org.hapticon.companion.bench.BenchReport
import org.hapticon.companion.bench.Benchmark

/** `hapticon bench [--json] [--quick]`: measurements to stdout, progress to stderr. */
fun runBench(args: List<String>, console: Console) {
    val arguments = Arguments.parse("bench", args, flagOptions = setOf("json", "quick"))
    arguments.requireNoPositionals()
    val config = if (arguments.flag("quick")) BenchConfig.QUICK else BenchConfig.FULL
    val result = Benchmark(config) { step -> console.err.println("bench: $step") }.run()
    console.out.println(if (arguments.flag("json")) BenchReport.json(result) else BenchReport.table(result))
}
