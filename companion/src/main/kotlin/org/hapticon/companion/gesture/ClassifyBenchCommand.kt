package org.hapticon.companion.gesture

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.plot.PngExport
import org.hapticon.gesture.recognition.WindowConfig
import java.io.File
import java.util.Locale

/**
 * `hapticon classify-bench [--people N] [--seed S] [--out DIR] [--quick]`: leave-one-participant-out accuracy
 * and latency of the gesture recogniser over window lengths and tree counts, as a table on stdout and, with
 * --out, `DIR/classify-bench.png`.
 */
fun runClassifyBench(args: List<String>, console: Console) {
    val arguments = Arguments.parse("classify-bench", args, valueOptions = setOf("people", "seed", "out"), flagOptions = setOf("quick"))
    arguments.requireNoPositionals()
    val quick = arguments.flag("quick")
    val people = arguments.int("people", if (quick) 3 else 6)
    if (people !in 2..50) throw UsageException("--people must be in 2..50 (one is held out), got $people")
    val seedText = arguments.value("seed")
    val seed = if (seedText == null) 1L else seedText.toLongOrNull() ?: throw UsageException("--seed must be a whole number, got '$seedText'")
    val out = arguments.value("out")?.let { File(it) }
    if (out != null) OutputFiles.ensureDirectory(out)
    val config = RecognitionBenchConfig(
        people = people,
        seed = seed,
        takesPerLabel = if (quick) 1 else 3,
        windows = listOf(0.25, 0.5, 1.0, 2.0),
        treeCounts = if (quick) listOf(10, 30) else listOf(10, 30, 100),
    )
    val started = System.nanoTime()
    val results = RecognitionBench.run(config) { console.err.println("classify-bench: $it") }
    val parallelSeconds = (System.nanoTime() - started) / 1e9
    console.out.print(formatTable(results, config))
    // The baseline: the same folds on one thread, in the same run. It runs second, with the JIT already warm,
    // so the printed speed-up errs low.
    val sequentialStarted = System.nanoTime()
    val sequential = RecognitionBench.run(config, parallel = false) { console.err.println("classify-bench (one thread): $it") }
    val sequentialSeconds = (System.nanoTime() - sequentialStarted) / 1e9
    console.out.println(formatSpeedUp(parallelSeconds, sequentialSeconds, Runtime.getRuntime().availableProcessors(), sameFigures(results, sequential)))
    val personal = RecognitionBench.personal(config, DEFAULT_TREES)
    console.out.println(
        String.format(
            Locale.ROOT, "personal model (%d takes per label, %.2f s window, %d trees): accuracy %.3f ± %.3f on 2 further takes, trained in %.0f ms",
            personal.examples, WindowConfig.DEFAULT_WINDOW_SECONDS, personal.trees, personal.accuracyMean, personal.accuracySd, personal.trainMillis,
        ),
    )
    if (out != null) console.err.println(PngExport.write(RecognitionPlot.draw(results, config), File(out, "classify-bench.png")))
}

/** The results as a fixed-width table, one row per (window, trees). */
internal fun formatTable(results: List<RecognitionResult>, config: RecognitionBenchConfig): String = buildString {
    append("leave-one-participant-out over ${config.people} simulated people (seed ${config.seed}), ${config.takesPerLabel} takes per label, 9 labels, hop 0.1 s\n")
    append(String.format(Locale.ROOT, "%-8s %-6s %-16s %-12s %-10s %s%n", "window", "trees", "accuracy", "latency_ms", "live_hits", "us_per_window"))
    for (r in results) {
        append(
            String.format(
                Locale.ROOT, "%-8s %-6d %-16s %-12s %-10s %.1f%n",
                "${r.windowSeconds}s", r.trees, String.format(Locale.ROOT, "%.3f ± %.3f", r.accuracyMean, r.accuracySd),
                if (r.latencyMs.isNaN()) "n/a" else String.format(Locale.ROOT, "%.0f", r.latencyMs),
                String.format(Locale.ROOT, "%.2f", r.liveHitRate), r.microsPerWindow,
            ),
        )
    }
}

/** Whether two runs agree on every figure but the timing (µs per window), as a run with one seed must. */
internal fun sameFigures(a: List<RecognitionResult>, b: List<RecognitionResult>): Boolean =
    a.size == b.size && a.zip(b).all { (x, y) ->
        x.windowSeconds == y.windowSeconds && x.trees == y.trees && x.accuracyMean == y.accuracyMean &&
            x.accuracySd == y.accuracySd && x.latencyMs.equals(y.latencyMs) && x.liveHitRate == y.liveHitRate
    }

/** The parallel run's wall time beside the one-thread baseline's from the same run, and their ratio. */
internal fun formatSpeedUp(parallelSeconds: Double, sequentialSeconds: Double, cores: Int, identical: Boolean): String = String.format(
    Locale.ROOT, "leave-one-out wall time: %.1f s on %d cores (folds in parallel), %.1f s on one thread (baseline, same run): speed-up %.2fx; figures %s",
    parallelSeconds, cores, sequentialSeconds, sequentialSeconds / parallelSeconds, if (identical) "identical" else "DIFFER",
)
