package org.hapticon.companion.bench

/**
 * How much work `hapticon bench` does. [FULL] is the measurement (about 25 s on 2 cores); [QUICK] runs
 * every part with tiny budgets, to check the bench itself works, and its figures mean little.
 *
 * @property sampleRate rate of the throughput, first-block and allocation measurements.
 * @property blockSamples size of the reused FloatArray every read loop fills.
 * @property warmupMillis time each throughput case runs before measuring, so the JIT has compiled it.
 * @property measureMillis time each throughput case is measured for, in whole runs.
 * @property minRuns fewest measured runs per throughput case, however long they take.
 * @property firstBlockRuns measured runs of the first-block latency per icon and mode (after as many warm-up runs).
 * @property allocationBlocks blocks read while counting allocated bytes.
 * @property errorRates sample rates at which FAST is compared with EXACT.
 * @property errorNotes MIDI notes compared (those at or above Nyquist for a rate are skipped).
 * @property errorSeconds length of each compared stream.
 * @property decodeBufferBytes size of each protocol's synthetic stream in the decoding measurement.
 * @property decodeRuns measured decoding runs per protocol (the median counts), after [decodeWarmupRuns].
 * @property decodeWarmupRuns unmeasured decoding runs per protocol, for the JIT.
 * @property modelWarmupMillis time each sensor model runs before measuring.
 * @property modelMeasureMillis time each sensor model is measured for, in whole runs.
 * @property latencySamples FSR samples whose grains count in the latency measurement, after [latencyWarmupSamples].
 * @property latencyWarmupSamples FSR samples sent through the latency path first, not counted.
 */
class BenchConfig(
    val sampleRate: Int,
    val blockSamples: Int,
    val warmupMillis: Long,
    val measureMillis: Long,
    val minRuns: Int,
    val firstBlockRuns: Int,
    val allocationBlocks: Int,
    val errorRates: List<Int>,
    val errorNotes: List<Double>,
    val errorSeconds: Double,
    val decodeBufferBytes: Int,
    val decodeRuns: Int,
    val decodeWarmupRuns: Int,
    val modelWarmupMillis: Long,
    val modelMeasureMillis: Long,
    val latencySamples: Int,
    val latencyWarmupSamples: Int,
) {
    companion object {
        val FULL: BenchConfig = BenchConfig(
            sampleRate = 44_100,
            blockSamples = 4096,
            warmupMillis = 700,
            measureMillis = 1_500,
            minRuns = 7,
            firstBlockRuns = 2_000,
            allocationBlocks = 256,
            errorRates = listOf(8_000, 22_050, 44_100, 48_000, 96_000, 192_000),
            errorNotes = listOf(0.0, 33.5, 57.0, 69.0, 100.0, 127.0),
            errorSeconds = 30.0,
            decodeBufferBytes = 16 shl 20,
            decodeRuns = 5,
            decodeWarmupRuns = 3,
            modelWarmupMillis = 300,
            modelMeasureMillis = 1_000,
            latencySamples = 100_000,
            latencyWarmupSamples = 10_000,
        )

        val QUICK: BenchConfig = BenchConfig(
            sampleRate = 44_100,
            blockSamples = 4096,
            warmupMillis = 10,
            measureMillis = 10,
            minRuns = 2,
            firstBlockRuns = 20,
            allocationBlocks = 16,
            errorRates = listOf(8_000, 44_100),
            errorNotes = listOf(0.0, 127.0),
            errorSeconds = 0.25,
            decodeBufferBytes = 256 shl 10,
            decodeRuns = 2,
            decodeWarmupRuns = 1,
            modelWarmupMillis = 10,
            modelMeasureMillis = 10,
            latencySamples = 2_000,
            latencyWarmupSamples = 500,
        )
    }
}
