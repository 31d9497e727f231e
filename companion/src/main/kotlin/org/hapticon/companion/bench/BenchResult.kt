package org.hapticon.companion.bench

import org.hapticon.core.render.EnvelopeModel

/** [min], [median] and [max] of one figure over [runs] repeated runs. */
data class Spread(val min: Double, val median: Double, val max: Double, val runs: Int) {
    companion object {
        /** The spread of [values] (non-empty). */
        fun of(values: List<Double>): Spread = Spread(values.min(), median(values), values.max(), values.size)
    }
}

/**
 * Samples per second over one workload of [samples] samples: the baselines [sineLoop] ([PlainSineLoop])
 * and [phasor] ([SinglePhasorLoop]), EXACT and FAST, timed in rotation in the same run; [exactVsSine] and
 * [fastVsPhasor] are the per-repeat ratios of our speed to the baseline's (> 1: ours is faster).
 */
data class Throughput(
    val workload: String,
    val samples: Long,
    val sineLoop: Spread,
    val phasor: Spread,
    val exact: Spread,
    val fast: Spread,
    val exactVsSine: Spread,
    val fastVsPhasor: Spread,
)

/**
 * Largest |FAST − EXACT| over a full stream of a full-scale icon at [note] and [sampleRate]: [maxAbsError]
 * between the float32 samples the streams yield, [maxAbsDoubleError] between the double samples before
 * narrowing (FAST's own error).
 */
data class ErrorCase(
    val model: EnvelopeModel,
    val sampleRate: Int,
    val note: Double,
    val samples: Long,
    val maxAbsError: Double,
    val maxAbsDoubleError: Double,
)

/** Median time from constructing the renderer to holding the first 10 ms of samples, per carrier mode. */
data class FirstBlock(val icon: String, val exactMicros: Double, val fastMicros: Double) {
    val worstMicros: Double get() = maxOf(exactMicros, fastMicros)
}

/** One performance target and whether this run met it. */
data class Target(val name: String, val goal: String, val measured: Double, val unit: String, val met: Boolean)

/** Everything one bench run measured. */
data class BenchResult(
    val sampleRate: Int,
    val blockSamples: Int,
    val throughputs: List<Throughput>,
    val errorCases: List<ErrorCase>,
    val firstBlockSamples: Int,
    val firstBlockRuns: Int,
    val firstBlocks: List<FirstBlock>,
    val allocatedBytesPerBlockExact: Double,
    val allocatedBytesPerBlockFast: Double,
    val sensors: SensorFigures,
    val elapsedSeconds: Double,
) {
    /** The worst FAST error case, compared as float32. */
    val worstError: ErrorCase get() = errorCases.maxBy { it.maxAbsError }

    /** The worst FAST error case compared in double precision. */
    val worstDoubleError: ErrorCase get() = errorCases.maxBy { it.maxAbsDoubleError }

    /**
     * The targets, each judged on its worst measured case (slowest workload, slowest icon): FAST's median
     * speed on one thread, EXACT's median speed ratio to the plain `Math.sin` loop; then the sensor
     * targets: decoding speed of CSV and framed streams, allocation while decoding (every protocol), grain
     * decision cost, and the sample-to-grain-command latency at the 99th percentile and at its worst.
     */
    val targets: List<Target>
        get() {
            val fast = throughputs.minOf { it.fast.median }
            val exactRatio = throughputs.minOf { it.exactVsSine.median }
            val firstBlock = firstBlocks.maxOf { it.worstMicros }
            val allocation = maxOf(allocatedBytesPerBlockExact, allocatedBytesPerBlockFast)
            return listOf(
                Target("fast", ">= 1000 M samples/s", fast / 1e6, "M samples/s", fast >= 1e9),
                Target("exactVsSine", ">= 0.9x plain sin", exactRatio, "x (median)", exactRatio >= 0.9),
                Target("firstBlock", "<= 50 µs", firstBlock, "µs", firstBlock <= 50.0),
                Target("allocation", "0 bytes/block", allocation, "bytes/block", allocation == 0.0),
            ) + sensorTargets()
        }

    private fun sensorTargets(): List<Target> {
        val csv = sensors.decode("csv").megabytesPerSecond
        val framed = sensors.decode("framed").megabytesPerSecond
        // NaN (a JVM that cannot count) fails the target rather than passing unmeasured.
        val decodeAllocation = sensors.decode.maxOf { it.bytesAllocatedPerFrame }
        val grainDecision = sensors.model("grainDecider").medianNanosPerSample
        val p99 = sensors.latency.p99Micros
        val worst = sensors.latency.maxMicros
        val freeCore = sensors.latency.maxWithoutRunQueueMicros
        return listOf(
            Target("decodeCsv", ">= 50 MB/s", csv, "MB/s", csv >= 50.0),
            Target("decodeFramed", ">= 50 MB/s", framed, "MB/s", framed >= 50.0),
            Target("decodeAllocation", "0 bytes/frame", decodeAllocation, "bytes/frame", decodeAllocation == 0.0),
            Target("grainDecision", "<= 1000 ns/sample", grainDecision, "ns/sample", grainDecision <= 1000.0),
            Target("grainLatencyP99", "<= 1000 µs", p99, "µs", p99 <= 1000.0),
            // The worst single sample: met on a quiet machine; a loaded one adds scheduler delays (docs/performance.md).
            Target("grainLatencyMax", "<= 1000 µs (quiet)", worst, "µs", worst <= 1000.0),
            // The same worst case with each grain's own run-queue wait (measured, not assumed) taken off: a free core.
            Target("grainLatencyMaxFreeCore", "<= 1000 µs", freeCore, "µs", freeCore <= 1000.0),
        )
    }
}
