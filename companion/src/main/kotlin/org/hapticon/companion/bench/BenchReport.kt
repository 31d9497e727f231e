package org.hapticon.companion.bench

import org.hapticon.core.io.SchemaJson
import java.util.Locale

/** Formats a [BenchResult] as a human-readable table or as one JSON object. */
object BenchReport {
    /** The table `hapticon bench` prints. */
    fun table(result: BenchResult): String = buildString {
        line("hapticon bench: paper model, %d Hz, reads into a reused %d-sample block", result.sampleRate, result.blockSamples)
        line("")
        line("throughput on one thread, M samples/s, min / median / max over %d+ runs timed in rotation", result.throughputs.minOf { it.exact.runs })
        for (t in result.throughputs) {
            line("  %s, %d samples", t.workload, t.samples)
            line("    %-12s %23s", "sin loop", rate(t.sineLoop))
            line("    %-12s %23s   ratio to sin loop %s", "exact", rate(t.exact), ratio(t.exactVsSine))
            line("    %-12s %23s", "phasor", rate(t.phasor))
            line("    %-12s %23s   ratio to phasor   %s", "fast", rate(t.fast), ratio(t.fastVsPhasor))
        }
        line("  sin loop = block[j] = sin(2π·f·i/fs) per sample; phasor = one rotating phasor; both a bare carrier")
        line("  (no envelope: less work than ours). Ratios are per repeat, ours / baseline, same run; > 1 is faster.")
        line("")
        val worst = result.worstError
        val rates = result.errorCases.map { it.sampleRate }.distinct().sorted()
        val notes = result.errorCases.map { it.note }.distinct().sorted()
        line(
            "FAST max |error| vs EXACT: %.3g over %d full streams (rates %s Hz; notes %s; both models)",
            worst.maxAbsError, result.errorCases.size, rates.joinToString(", "), notes.joinToString(", ") { number(it) },
        )
        line("  worst: note %s at %d Hz, %s model, %d samples", number(worst.note), worst.sampleRate, worst.model.name.lowercase(), worst.samples)
        line("  compared as the float32 samples the stream yields; one float32 step just below 1.0 is 5.96e-08")
        val worstDouble = result.worstDoubleError
        line("FAST max |error| vs EXACT in double precision: %.3g over the same streams, read as doubles before narrowing", worstDouble.maxAbsDoubleError)
        line("  worst: note %s at %d Hz, %s model, %d samples", number(worstDouble.note), worstDouble.sampleRate, worstDouble.model.name.lowercase(), worstDouble.samples)
        line("")
        line(
            "time to the first 10 ms block (%d samples), µs, median of %d runs: renderer construction to samples in hand",
            result.firstBlockSamples, result.firstBlockRuns,
        )
        line("  %-9s %9s %9s", "icon", "exact", "fast")
        for (f in result.firstBlocks) line("  %-9s %9.1f %9.1f", f.icon, f.exactMicros, f.fastMicros)
        line("")
        line(
            "allocated bytes per block in steady state: exact %s, fast %s",
            number(result.allocatedBytesPerBlockExact), number(result.allocatedBytesPerBlockFast),
        )
        line("")
        sensors(result.sensors)
        line("")
        line("targets (each judged on its worst case)")
        for (target in result.targets) {
            line("  %-16s %-20s measured %10s %-12s %s", target.name, target.goal, number(target.measured), target.unit, if (target.met) "met" else "NOT MET")
        }
        line("")
        line("total %.1f s", result.elapsedSeconds)
    }.trimEnd()

    private fun StringBuilder.sensors(sensors: SensorFigures) {
        line("sensor decoding on one core: synthetic streams fed in %d-byte reads, median of the runs", ProtocolBenchmark.DEFAULT_READ_SIZE)
        line("  %-17s %7s %9s %11s %12s", "protocol", "MB", "MB/s", "M frames/s", "bytes/frame")
        for (d in sensors.decode) {
            line("  %-17s %7.1f %9.1f %11.2f %12s", d.name, d.bytes / 1e6, d.megabytesPerSecond, d.framesPerSecond / 1e6, allocation(d.bytesAllocatedPerFrame))
        }
        line("sensor models, ns per sample (median / best) and bytes allocated per sample")
        for (m in sensors.models) {
            line("  %-17s %8.1f / %6.1f %12s", m.name, m.medianNanosPerSample, m.bestNanosPerSample, allocation(m.allocatedBytesPerSample))
        }
        val latency = sensors.latency
        line(
            "fake-port FSR sample to grain command, µs: p50 %.1f, p99 %.1f, max %.1f (%d grains from %d samples at 1 kHz)",
            latency.p50Micros, latency.p99Micros, latency.maxMicros, latency.grains, latency.samples,
        )
        line(
            "  the worst grain waited %.1f µs runnable in the OS run queue%s; worst grain without its run-queue wait %.1f µs;" +
                " over 1 ms: %d grains, %d of them under 1 ms without that wait, %d with a GC",
            latency.runQueueMicrosAtMax, if (latency.gcAtMax) " and saw a GC" else ", no GC", latency.maxWithoutRunQueueMicros,
            latency.over1ms, latency.over1msByRunQueue, latency.over1msWithGc,
        )
        line(
            "  bytes allocated per sample: %s from decoded frame to command encoded; %s on the whole reader thread (with the fake port's own)",
            allocation(latency.handlerBytesPerSample), allocation(latency.readerBytesPerSample),
        )
        line("  reader thread CPU: %s", readerCpu(latency))
        val baseline = sensors.latencyBaseline
        line(
            "  baseline, same run (the engine's arithmetic re-created, no GrainEngine): p50 %.1f, p99 %.1f, max %.1f µs (%d grains);" +
                " without run-queue wait %.1f µs; %s bytes per sample",
            baseline.p50Micros, baseline.p99Micros, baseline.maxMicros, baseline.grains, baseline.maxWithoutRunQueueMicros,
            allocation(baseline.handlerBytesPerSample),
        )
        line("  framed sample written to a BenchSerialLine -> SensorReader thread -> FramedDecoder -> LiveFrame -> GrainEngine")
        line("  (FSR force, GrainDecider) -> its GrainSink encodes the set-outputs command, written back; one sample in flight at a time")
    }

    /**
     * One run of `bench --grain` on one line: p50, p99, max; the worst grain's run-queue wait, time in a
     * safepoint and steal; the worst grain without its own wait; the grains over 1 ms by cause (a grain may have
     * several) and how many no cause explains; the run's safepoints and steal; allocation and the reader's CPU.
     */
    fun grainLine(r: GrainLatencyResult): String = String.format(
        Locale.ROOT,
        "p50 %.1f, p99 %.1f, max %.1f (%d grains); worst waited %.1f in the run queue%s, %s in a safepoint, steal %s;" +
            " max without that wait %.1f; over 1 ms: %d (%d by run-queue wait, %d by a safepoint, %d by both together," +
            " %d with a GC, %d with steal, %d unexplained); %s; steal %s of CPU time; %s bytes/sample frame to command; reader CPU %s",
        r.p50Micros, r.p99Micros, r.maxMicros, r.grains, r.runQueueMicrosAtMax, if (r.gcAtMax) " and saw a GC" else "",
        if (r.safepointMicrosAtMax.isNaN()) "unknown" else String.format(Locale.ROOT, "%.1f", r.safepointMicrosAtMax),
        if (r.stealTicksAtMax < 0) "n/a" else "${r.stealTicksAtMax} ticks",
        r.maxWithoutRunQueueMicros, r.over1ms, r.over1msByRunQueue, r.over1msBySafepoint, r.over1msByWaitAndSafepoint,
        r.over1msWithGc, r.over1msBySteal, r.over1msUnexplained, safepoints(r),
        if (r.stealShare.isNaN()) "unknown" else String.format(Locale.ROOT, "%.2f %%", r.stealShare * 100),
        allocation(r.handlerBytesPerSample), readerCpu(r),
    )

    private fun safepoints(r: GrainLatencyResult): String =
        if (r.safepoints < 0) "safepoints not logged"
        else if (r.safepoints == 0) "0 safepoints"
        else String.format(Locale.ROOT, "%d safepoints, longest %.1f (%s)", r.safepoints, r.longestSafepointMicros, r.longestSafepoint)

    private fun readerCpu(r: GrainLatencyResult): String =
        if (r.readerCpuMicrosPerSample.isNaN()) "not measured"
        else String.format(Locale.ROOT, "%.2f µs per sample, %.1f %% of one core", r.readerCpuMicrosPerSample, r.readerCpuShare * 100)

    /** One JSON object with every figure ([BenchDocument]); rates in samples per second, times in µs. */
    fun json(result: BenchResult): String = SchemaJson.encode(BenchDocument.serializer(), document(result), "  ")

    private fun document(result: BenchResult): BenchDocument = BenchDocument(
        sampleRate = result.sampleRate,
        blockSamples = result.blockSamples,
        throughput = result.throughputs.map { t ->
            ThroughputDocument(
                t.workload, t.samples, spread(t.sineLoop, 0), spread(t.phasor, 0), spread(t.exact, 0), spread(t.fast, 0),
                spread(t.exactVsSine, 3), spread(t.fastVsPhasor, 3),
            )
        },
        fastMaxAbsError = result.worstError.maxAbsError,
        fastMaxAbsErrorDouble = result.worstDoubleError.maxAbsDoubleError,
        fastErrorCases = result.errorCases.map { e ->
            ErrorCaseDocument(e.model.name.lowercase(), e.sampleRate, e.note, e.samples, e.maxAbsError, e.maxAbsDoubleError)
        },
        firstBlockSamples = result.firstBlockSamples,
        firstBlockMicros = result.firstBlocks.map { FirstBlockDocument(it.icon, rounded(it.exactMicros, 2), rounded(it.fastMicros, 2)) },
        allocatedBytesPerBlock = AllocationDocument(result.allocatedBytesPerBlockExact, result.allocatedBytesPerBlockFast),
        sensors = sensorsDocument(result.sensors),
        targets = result.targets.associateTo(LinkedHashMap()) { it.name to TargetDocument(it.goal, measured(it.measured, 3), it.unit, it.met) },
        elapsedSeconds = rounded(result.elapsedSeconds, 2),
    )

    private fun sensorsDocument(sensors: SensorFigures): SensorsDocument = SensorsDocument(
        decode = sensors.decode.map { d ->
            DecodeDocument(
                d.name, d.bytes, d.frames, rounded(d.megabytesPerSecond, 2), Math.round(d.framesPerSecond), measured(d.bytesAllocatedPerFrame, 3),
            )
        },
        models = sensors.models.map { m ->
            ModelDocument(
                m.name, rounded(m.medianNanosPerSample, 2), rounded(m.bestNanosPerSample, 2), measured(m.allocatedBytesPerSample, 3),
                m.samplesPerRun, m.runs,
            )
        },
        grainLatency = with(sensors.latency) {
            GrainLatencyDocument(
                samples, grains, rounded(p50Micros, 2), rounded(p99Micros, 2), rounded(maxMicros, 2), measured(runQueueMicrosAtMax, 2),
                gcAtMax, measured(maxWithoutRunQueueMicros, 2), over1ms, over1msByRunQueue, over1msWithGc, over1msBySafepoint,
                over1msByWaitAndSafepoint, over1msBySteal, over1msUnexplained,
                // -1, NaN and "" mean "not logged" (no safepoint log, not Linux): left out, as measured() does.
                safepoints.takeIf { it >= 0 }, measured(longestSafepointMicros, 1), longestSafepoint.takeIf { it.isNotEmpty() },
                measured(safepointMicrosAtMax, 1), stealTicksAtMax.takeIf { it >= 0 }, measured(stealShare * 100, 2),
                measured(handlerBytesPerSample, 3), measured(readerBytesPerSample, 3), measured(readerCpuMicrosPerSample, 3),
                measured(readerCpuShare, 3),
            )
        },
        grainLatencyBaseline = with(sensors.latencyBaseline) {
            GrainLatencyBaselineDocument(
                samples, grains, rounded(p50Micros, 2), rounded(p99Micros, 2), rounded(maxMicros, 2), measured(maxWithoutRunQueueMicros, 2),
                measured(handlerBytesPerSample, 3),
            )
        },
    )

    /** [value] rounded, or null (left out) where it was not measured: NaN or negative, as the sensor benchmarks say so. */
    private fun measured(value: Double, decimals: Int): Double? = if (value.isNaN() || value < 0) null else rounded(value, decimals)

    /** An allocation figure for the table; `n/a` where the JVM could not count. */
    private fun allocation(bytes: Double): String = if (bytes.isNaN() || bytes < 0) "n/a" else number(bytes)

    /** Rates in samples per second (whole), ratios with [decimals]. */
    private fun spread(spread: Spread, decimals: Int): SpreadDocument =
        SpreadDocument(rounded(spread.min, decimals), rounded(spread.median, decimals), rounded(spread.max, decimals), spread.runs)

    private fun rounded(value: Double, decimals: Int): Double = Math.round(value * POWERS[decimals]) / POWERS[decimals]

    private val POWERS = doubleArrayOf(1.0, 10.0, 100.0, 1000.0)

    private fun rate(rate: Spread): String =
        String.format(Locale.ROOT, "%.0f / %.0f / %.0f", rate.min / 1e6, rate.median / 1e6, rate.max / 1e6)

    private fun ratio(ratio: Spread): String =
        String.format(Locale.ROOT, "%.2f× / %.2f× / %.2f×", ratio.min, ratio.median, ratio.max)

    /** Whole numbers without a fraction, others with up to 3 significant decimals. */
    private fun number(value: Double): String =
        if (value == Math.rint(value)) String.format(Locale.ROOT, "%.0f", value) else String.format(Locale.ROOT, "%.3g", value)

    private fun StringBuilder.line(format: String, vararg args: Any) {
        append(String.format(Locale.ROOT, format, *args)).append('\n')
    }
}
