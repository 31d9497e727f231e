package org.hapticon.companion

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.bench.BenchConfig
import org.hapticon.companion.bench.BenchReport
import org.hapticon.companion.bench.Benchmark
import org.hapticon.companion.chat.runMessagingBench
import org.hapticon.companion.study.AnalysisBench

/** `hapticon bench [--json] [--quick] [--messaging | --analysis]`: measurements to stdout, progress to stderr. */
fun runBench(args: List<String>, console: Console) {
    val arguments = Arguments.parse("bench", args, flagOptions = setOf("json", "quick", "messaging", "analysis"))
    arguments.requireNoPositionals()
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
