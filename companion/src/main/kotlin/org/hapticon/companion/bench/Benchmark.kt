package org.hapticon.companion.bench

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.IconRenderer
import org.hapticon.core.render.RenderMode
import org.hapticon.core.render.SampleStream
import java.lang.management.ManagementFactory
import kotlin.math.abs
import kotlin.math.ceil

/**
 * Runs the measurements of `hapticon bench` as [config] says, reporting each step to [progress].
 * All renders use the paper model at [BenchConfig.sampleRate] unless stated; every read loop fills one
 * reused FloatArray of [BenchConfig.blockSamples], as a real consumer does.
 */
class Benchmark(private val config: BenchConfig, private val progress: (String) -> Unit = {}) {
    private val block = FloatArray(config.blockSamples)

    /** Sum of one sample per block read, kept so the JIT cannot discard the work being timed. */
    var checksum: Double = 0.0
        private set

    /** Runs every measurement in turn, the [SensorBench] last; takes about 25 s with [BenchConfig.FULL]. */
    fun run(): BenchResult {
        val started = System.nanoTime()
        val throughputs = WORKLOADS.map { (name, icons) ->
            progress("throughput over $name (plain sine, single phasor, exact, fast)")
            throughput(name, icons)
        }
        progress("FAST error against EXACT")
        val errors = errorCases()
        progress("time to the first 10 ms block")
        val firstBlockSamples = ceil(FIRST_BLOCK_SECONDS * config.sampleRate).toInt()
        val firstBlocks = (HapticIcon.PRESETS + LONGEST).map { firstBlock(it, firstBlockSamples) }
        progress("allocation per block")
        val exactBytes = allocatedBytesPerBlock(RenderMode.EXACT)
        val fastBytes = allocatedBytesPerBlock(RenderMode.FAST)
        val sensors = SensorBench(config, progress).run()
        return BenchResult(
            sampleRate = config.sampleRate,
            blockSamples = config.blockSamples,
            throughputs = throughputs,
            errorCases = errors,
            firstBlockSamples = firstBlockSamples,
            firstBlockRuns = config.firstBlockRuns,
            firstBlocks = firstBlocks,
            allocatedBytesPerBlockExact = exactBytes,
            allocatedBytesPerBlockFast = fastBytes,
            sensors = sensors,
            elapsedSeconds = (System.nanoTime() - started) / 1e9,
        )
    }

    /**
     * The four loops over one workload, timed in rotation (plain sine, single phasor, EXACT, FAST, then
     * again), so a slow moment of a loaded machine hits all four alike; each repeat also gives the ratios
     * EXACT / plain sine and FAST / single phasor of that repeat.
     */
    private fun throughput(name: String, icons: List<HapticIcon>): Throughput {
        val rate = config.sampleRate
        // Renderers are built once: throughput is about reading streams; construction has its own figure.
        val exact = icons.map { IconRenderer(it, rate, EnvelopeModel.PAPER, RenderMode.EXACT) }
        val fast = icons.map { IconRenderer(it, rate, EnvelopeModel.PAPER, RenderMode.FAST) }
        val samples = exact.sumOf { it.sampleCount }
        val loops: List<() -> Unit> = listOf(
            { for (r in exact) drain(PlainSineLoop(r.icon.frequency, rate, r.sampleCount)) },
            { for (r in exact) drain(SinglePhasorLoop(r.icon.frequency, rate, r.sampleCount)) },
            { for (renderer in exact) drain(renderer.stream()) },
            { for (renderer in fast) drain(renderer.stream()) },
        )
        val warmUntil = System.nanoTime() + config.warmupMillis * 1_000_000
        do loops.forEach { it() } while (System.nanoTime() < warmUntil)
        val rates = List(loops.size) { ArrayList<Double>() }
        val measureUntil = System.nanoTime() + config.measureMillis * 1_000_000
        while (rates[0].size < config.minRuns || System.nanoTime() < measureUntil) {
            for ((k, loop) in loops.withIndex()) {
                val start = System.nanoTime()
                loop()
                rates[k] += samples / ((System.nanoTime() - start) / 1e9)
            }
        }
        return Throughput(
            workload = name,
            samples = samples,
            sineLoop = Spread.of(rates[0]),
            phasor = Spread.of(rates[1]),
            exact = Spread.of(rates[2]),
            fast = Spread.of(rates[3]),
            exactVsSine = Spread.of(rates[2].indices.map { rates[2][it] / rates[0][it] }),
            fastVsPhasor = Spread.of(rates[3].indices.map { rates[3][it] / rates[1][it] }),
        )
    }

    private fun drain(stream: SampleStream) {
        while (true) {
            val count = stream.read(block, 0, block.size)
            if (count < 0) return
            checksum += block[count - 1]
        }
    }

    private fun drain(loop: BaselineLoop) {
        while (true) {
            val count = loop.read(block)
            if (count < 0) return
            checksum += block[count - 1]
        }
    }

    private fun errorCases(): List<ErrorCase> {
        val cases = ArrayList<ErrorCase>()
        for (model in EnvelopeModel.values()) {
            for (rate in config.errorRates) {
                for (note in config.errorNotes) {
                    // A full-scale hold makes the envelope 1, so the difference is the carrier's alone.
                    val icon = HapticIcon("full-scale", 0.0, config.errorSeconds, 1.0, 0.0, note)
                    if (icon.frequency >= rate / 2.0) continue
                    cases += errorCase(icon, rate, model)
                }
            }
        }
        return cases
    }

    /**
     * Reads both streams as doubles, and compares them both as they are and narrowed to the float32
     * samples a float read yields (float reads narrow the very same doubles).
     */
    private fun errorCase(icon: HapticIcon, rate: Int, model: EnvelopeModel): ErrorCase {
        val exact = IconRenderer(icon, rate, model, RenderMode.EXACT).stream()
        val fast = IconRenderer(icon, rate, model, RenderMode.FAST).stream()
        val exactBlock = DoubleArray(block.size)
        val fastBlock = DoubleArray(block.size)
        var maxFloatError = 0.0
        var maxDoubleError = 0.0
        while (true) {
            val count = exact.read(exactBlock, 0, exactBlock.size)
            if (count < 0) break
            check(fast.read(fastBlock, 0, count) == count) { "FAST stream is shorter than EXACT" }
            for (j in 0 until count) {
                maxDoubleError = maxOf(maxDoubleError, abs(exactBlock[j] - fastBlock[j]))
                maxFloatError = maxOf(maxFloatError, abs(exactBlock[j].toFloat().toDouble() - fastBlock[j].toFloat().toDouble()))
            }
        }
        return ErrorCase(model, rate, icon.note, exact.totalSamples, maxFloatError, maxDoubleError)
    }

    private fun firstBlock(icon: HapticIcon, samples: Int): FirstBlock {
        fun medianMicros(mode: RenderMode): Double {
            repeat(config.firstBlockRuns) { firstBlockNanos(icon, mode, samples) }
            val runs = DoubleArray(config.firstBlockRuns) { firstBlockNanos(icon, mode, samples) / 1e3 }
            return median(runs.asList())
        }
        return FirstBlock(icon.name, medianMicros(RenderMode.EXACT), medianMicros(RenderMode.FAST))
    }

    /** Nanoseconds from constructing a renderer to holding its first [samples] samples. */
    private fun firstBlockNanos(icon: HapticIcon, mode: RenderMode, samples: Int): Long {
        val start = System.nanoTime()
        val stream = IconRenderer(icon, config.sampleRate, EnvelopeModel.PAPER, mode).stream()
        var filled = 0
        while (filled < samples) {
            val count = stream.read(block, filled, samples - filled)
            if (count < 0) break
            filled += count
        }
        val elapsed = System.nanoTime() - start
        checksum += block[0]
        return elapsed
    }

    /** Bytes the current thread allocates per block read, after the stream's first blocks (steady state). */
    private fun allocatedBytesPerBlock(mode: RenderMode): Double {
        val threads = ManagementFactory.getThreadMXBean() as com.sun.management.ThreadMXBean
        check(threads.isThreadAllocatedMemorySupported && threads.isThreadAllocatedMemoryEnabled) {
            "this JVM cannot count allocated bytes per thread"
        }
        val stream = IconRenderer(LONGEST, config.sampleRate, EnvelopeModel.PAPER, mode).stream()
        repeat(STEADY_STATE_AFTER_BLOCKS) { stream.read(block, 0, block.size) }
        val thread = Thread.currentThread().id
        // The counter's own cost, subtracted so that only reading is counted.
        val overhead = (1..5).minOf { threads.getThreadAllocatedBytes(thread).let { before -> threads.getThreadAllocatedBytes(thread) - before } }
        // The least over three windows: a per-block allocation shows in every window, a one-off (JIT,
        // class loading, a cold JVM) in one only.
        var fewest = Long.MAX_VALUE
        var blocks = 0
        repeat(ALLOCATION_WINDOWS) {
            val before = threads.getThreadAllocatedBytes(thread)
            var read = 0
            while (read < config.allocationBlocks && stream.read(block, 0, block.size) > 0) read++
            val allocated = threads.getThreadAllocatedBytes(thread) - before - overhead
            if (read > 0 && allocated < fewest) {
                fewest = allocated
                blocks = read
            }
        }
        check(blocks > 0) { "the stream ended before steady state" }
        return fewest.coerceAtLeast(0L).toDouble() / blocks
    }

    companion object {
        private const val ALLOCATION_WINDOWS = 3

        /** The longest icon the safety caps allow ([HapticIcon.LONGEST_ALLOWED]): 64 overlapping repetitions, exactly 30 s. */
        val LONGEST: HapticIcon = HapticIcon.LONGEST_ALLOWED

        /** Named workloads of the throughput measurement. */
        val WORKLOADS: List<Pair<String, List<HapticIcon>>> = listOf("longest" to listOf(LONGEST), "presets" to HapticIcon.PRESETS)

        private const val FIRST_BLOCK_SECONDS = 0.010
        private const val STEADY_STATE_AFTER_BLOCKS = 4
    }
}

/** The median of [values] (mean of the middle two for an even count). */
fun median(values: List<Double>): Double {
    require(values.isNotEmpty()) { "median of nothing" }
    val sorted = values.sorted()
    val middle = sorted.size / 2
    return if (sorted.size % 2 == 1) sorted[middle] else (sorted[middle - 1] + sorted[middle]) / 2
}
