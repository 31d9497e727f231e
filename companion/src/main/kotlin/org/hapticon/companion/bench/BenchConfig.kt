package org.hapticon.companion.bench

/**
 * How much work `hapticon bench` does. [FULL] is the measurement (about 30 s on 2 cores); [QUICK] runs
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
        )
    }
}
