package org.hapticon.companion.study

import java.io.File
import java.io.OutputStream
import java.io.PrintStream
import java.lang.management.ManagementFactory
import java.lang.management.MemoryType
import java.nio.file.Files
import java.util.Locale
import java.util.SplittableRandom
import org.apache.commons.csv.CSVFormat
import org.hapticon.companion.bench.median
import org.hapticon.companion.cli.Console
import org.hapticon.study.export.Csv

/**
 * `hapticon bench --analysis`: the whole of `hapticon analyze` (reading the CSV file, descriptives,
 * paired t and Wilcoxon tests with Holm, the tables and one box plot per task written to disk) over
 * synthetic results of growing size, to show its cost grows linearly with the rows. The growth ratio
 * of each size is its median time over the previous size's; linear cost gives the ratio of the rows (10).
 */
class AnalysisBench(private val config: Config, private val progress: (String) -> Unit = {}) {
    /**
     * How much work to do.
     *
     * @property rows the sizes measured, each 10× the one before it.
     * @property runs measured runs per size (after one unmeasured run of the smallest size, for the JIT).
     */
    class Config(val rows: List<Int>, val runs: Int) {
        companion object {
            val FULL: Config = Config(listOf(10_000, 100_000, 1_000_000), runs = 3)
            val QUICK: Config = Config(listOf(1_000, 10_000), runs = 2)
        }
    }

    /**
     * One size: [rows] responses of [participants] participants in a [bytes]-byte file; [seconds] per run;
     * [peakHeapBytes] the most heap any run held (sum of the heap pools' peaks, so an upper bound); [gcSeconds]
     * the collectors' time over all runs.
     */
    class Size(
        val rows: Int,
        val participants: Int,
        val bytes: Long,
        val seconds: List<Double>,
        val peakHeapBytes: Long,
        val gcSeconds: Double,
        val read: ReadTimes,
    ) {
        val medianSeconds: Double get() = median(seconds)
    }

    /**
     * Reading the same file's records only (no analysis), [ours] with our one CSV reader ([Csv.forEachRecord]) and
     * [commonsCsv] with Apache Commons CSV's RFC 4180 parser, alternating, seconds per run: the baseline that
     * justifies keeping our reader (docs/study-analysis.md).
     */
    class ReadTimes(val ours: List<Double>, val commonsCsv: List<Double>)

    /** Generates each size's file into a temporary directory (deleted afterwards) and measures it. */
    fun run(): List<Size> {
        val dir = Files.createTempDirectory("hapticon-analysis-bench").toFile()
        try {
            val first = File(dir, "warmup.csv")
            writeResults(first, config.rows.first())
            progress("analysis: one unmeasured run of ${config.rows.first()} rows")
            analyze(first, File(dir, "out"))
            return config.rows.map { rows ->
                val csv = File(dir, "results-$rows.csv")
                val participants = writeResults(csv, rows)
                progress("analysis: $rows rows, ${config.runs} runs")
                val pools = ManagementFactory.getMemoryPoolMXBeans().filter { it.type == MemoryType.HEAP }
                val collectors = ManagementFactory.getGarbageCollectorMXBeans()
                val gcBefore = collectors.sumOf { it.collectionTime }
                var peak = 0L
                val seconds = List(config.runs) {
                    System.gc()
                    pools.forEach { it.resetPeakUsage() }
                    val start = System.nanoTime()
                    analyze(csv, File(dir, "out"))
                    val elapsed = (System.nanoTime() - start) / 1e9
                    peak = maxOf(peak, pools.sumOf { it.peakUsage.used })
                    elapsed
                }
                val gcSeconds = (collectors.sumOf { it.collectionTime } - gcBefore) / 1e3
                Size(rows, participants, csv.length(), seconds, peak, gcSeconds, readTimes(csv)).also { csv.delete() }
            }
        } finally {
            dir.deleteRecursively()
        }
    }

    private fun readTimes(csv: File): ReadTimes {
        val ours = ArrayList<Double>()
        val commons = ArrayList<Double>()
        // Both readers must see every field of every record (header included), or the comparison is void.
        val fields = csv.bufferedReader().useLines { lines -> lines.sumOf { it.split(',').size.toLong() } }
        repeat(config.runs) {
            ours += timed(csv, fields) { reader -> var n = 0L; Csv.forEachRecord(reader, csv.name) { n += it.fields.size }; n }
            commons += timed(csv, fields) { reader -> CSVFormat.RFC4180.parse(reader).use { parser -> parser.sumOf { it.size().toLong() } } }
        }
        return ReadTimes(ours, commons)
    }

    private fun timed(csv: File, fields: Long, read: (java.io.Reader) -> Long): Double {
        val start = System.nanoTime()
        val seen = csv.bufferedReader().use(read)
        val elapsed = (System.nanoTime() - start) / 1e9
        check(seen == fields) { "a reader saw $seen of the file's $fields fields" }
        return elapsed
    }

    private fun analyze(csv: File, out: File) {
        val nowhere = PrintStream(OutputStream.nullOutputStream())
        runAnalyze(listOf(csv.path, "--out", out.path, "--holm"), Console(nowhere, nowhere))
    }

    companion object {
        /** Tasks, icons and trials of the synthetic study; participants grow with the rows. */
        val TASKS: List<String> = listOf("calm", "urgent", "pleasant", "natural")
        val ICONS: List<String> = listOf("stroke", "hit", "knock", "hug", "tap", "pulse")
        const val TRIALS: Int = 5

        /** Every 97th participant skips the last icon, so some pairs drop participants as real data does. */
        private const val SKIPPER_EVERY = 97

        /**
         * Writes about [rows] synthetic responses (Likert 1..5, each icon with its own mean, seed 1) as a
         * long-format results CSV with a trial column; returns the number of participants.
         */
        fun writeResults(file: File, rows: Int): Int {
            val participants = maxOf(2, rows / (TASKS.size * ICONS.size * TRIALS))
            val random = SplittableRandom(1)
            file.bufferedWriter().use { w ->
                w.write("participant,task,icon,trial,response\n")
                for (p in 1..participants) {
                    val id = String.format(Locale.ROOT, "P%06d", p)
                    for (task in TASKS) for ((i, icon) in ICONS.withIndex()) {
                        if (p % SKIPPER_EVERY == 0 && i == ICONS.size - 1) continue
                        for (trial in 1..TRIALS) {
                            val rating = (1 + i % 4 + random.nextInt(3) - 1).coerceIn(1, 5)
                            w.write("$id,$task,$icon,$trial,$rating\n")
                        }
                    }
                }
            }
            return participants
        }

        /** The table `hapticon bench --analysis` prints. */
        fun table(sizes: List<Size>): String = buildString {
            fun line(format: String, vararg args: Any) = append(String.format(Locale.ROOT, format, *args)).append('\n')
            line("hapticon analyze (read CSV, describe, t + Wilcoxon + Holm, tables, box plots) on synthetic results")
            line("  %d tasks x %d icons x %d trials per participant; seconds per run (min / median / max)", TASKS.size, ICONS.size, TRIALS)
            line("  %9s %12s %9s %24s %10s %8s %12s %9s", "rows", "participants", "MB", "seconds", "µs/row", "growth", "peak heap MB", "GC s")
            var previous: Size? = null
            for (s in sizes) {
                val growth = previous?.let { String.format(Locale.ROOT, "%.2fx", s.medianSeconds / it.medianSeconds) } ?: "-"
                line(
                    "  %9d %12d %9.1f %24s %10.2f %8s %12.0f %9.2f", s.rows, s.participants, s.bytes / 1e6,
                    String.format(Locale.ROOT, "%.3f / %.3f / %.3f", s.seconds.min(), s.medianSeconds, s.seconds.max()),
                    s.medianSeconds * 1e6 / s.rows, growth, s.peakHeapBytes / 1e6, s.gcSeconds,
                )
                previous = s
            }
            line("  reading the records only (median ms of %d runs, same file, alternating):", sizes.firstOrNull()?.read?.ours?.size ?: 0)
            line("  %9s %14s %14s %8s", "rows", "our reader", "commons-csv", "ratio")
            for (s in sizes) {
                val ours = median(s.read.ours)
                val commons = median(s.read.commonsCsv)
                line("  %9d %14.1f %14.1f %7.2fx", s.rows, ours * 1e3, commons * 1e3, commons / ours)
            }
            line("  growth = median time over the previous size's, for 10x the rows: linear cost gives 10x")
            line("  peak heap = sum of the heap pools' peaks in the worst run (an upper bound on heap in use)")
        }.trimEnd()
    }
}
