package org.hapticon.sensor.grains

import org.hapticon.sensor.glove.HandRegion
import org.hapticon.sensor.glove.HandshakeSession
import java.lang.management.ManagementFactory
import kotlin.math.PI
import kotlin.math.sin

/**
 * The per-sample cost of one sensor model: median and best nanoseconds per sample over [runs] timed runs of
 * [samplesPerRun] samples, and the bytes the measuring thread allocated per sample in steady state
 * ([allocatedBytesPerSample], -1 when the JVM cannot count them).
 */
public data class SensorBenchmarkResult(
    val name: String,
    val medianNanosPerSample: Double,
    val bestNanosPerSample: Double,
    val allocatedBytesPerSample: Double,
    val samplesPerRun: Int,
    val runs: Int,
)

/**
 * Measures the sensor models' hot paths, for `hapticon bench`:
 * - `grainDecider`: [GrainDecider.offer] (filter, bin, decision) on a 1 kHz synthetic press-and-release
 *   force with 39 convex bins;
 * - `handshakePressure`: [HandshakeSession.computeInto] for both hands' thumb and middle angles (two
 *   detectors, six region pressures, actuator angles, servo values and amplitudes) per sample.
 *
 * Inputs are precomputed so only the model is timed. Each case is warmed up for [warmupMillis], then timed
 * in whole runs for at least [measureMillis] and [MIN_RUNS] runs.
 */
public object SensorModelBenchmark {
    /** Fewest timed runs per case. */
    public const val MIN_RUNS: Int = 5

    private const val SAMPLES = 1 shl 16

    /** Bits of the models' outputs, kept so the JIT cannot discard the work being timed. */
    @Volatile
    public var checksum: Long = 0
        private set

    /**
     * Runs both cases and returns their results in the order `grainDecider`, `handshakePressure`.
     * @throws IllegalArgumentException when a duration is negative.
     */
    public fun run(warmupMillis: Long = 300, measureMillis: Long = 1000): List<SensorBenchmarkResult> {
        require(warmupMillis >= 0 && measureMillis >= 0) { "durations must be >= 0, were $warmupMillis and $measureMillis ms" }
        return listOf(grainDecider(warmupMillis, measureMillis), handshakePressure(warmupMillis, measureMillis))
    }

    private fun grainDecider(warmupMillis: Long, measureMillis: Long): SensorBenchmarkResult {
        // Presses from 0 to 10 N and back every 2 s, with a little ripple so bins are crossed both ways.
        val forces = DoubleArray(SAMPLES) { i -> 5.0 - 5.0 * kotlin.math.cos(2 * PI * i / 2000.0) + 0.05 * sin(2 * PI * i / 7.0) }
        val decider = GrainDecider(GrainSettings(grainCount = 39, distribution = BinDistribution.CONVEX), 1000.0)
        val pass = {
            var fired = 0L
            for (force in forces) if (decider.offer(force)) fired++
            checksum += fired
        }
        return measure("grainDecider", warmupMillis, measureMillis, pass)
    }

    private fun handshakePressure(warmupMillis: Long, measureMillis: Long): SensorBenchmarkResult {
        // Both hands close to 90° and open again every 2 s, the partner a quarter period behind.
        val selfMiddle = DoubleArray(SAMPLES) { i -> 45.0 - 45.0 * kotlin.math.cos(2 * PI * i / 200.0) }
        val partnerMiddle = DoubleArray(SAMPLES) { i -> 45.0 - 45.0 * kotlin.math.cos(2 * PI * (i - 50) / 200.0) }
        val session = HandshakeSession()
        val regions = HandRegion.ALL.size
        val pressures = DoubleArray(regions)
        val angles = DoubleArray(regions)
        val servos = IntArray(regions)
        val amplitudes = IntArray(regions)
        val pass = {
            var sum = 0L
            for (i in 0 until SAMPLES) {
                session.computeInto(selfMiddle[i] * 0.8, selfMiddle[i], partnerMiddle[i] * 0.8, partnerMiddle[i], pressures, angles, servos, amplitudes)
                sum += servos[0] + amplitudes[5]
            }
            checksum += sum
        }
        return measure("handshakePressure", warmupMillis, measureMillis, pass)
    }

    private fun measure(name: String, warmupMillis: Long, measureMillis: Long, pass: () -> Unit): SensorBenchmarkResult {
        val warmUntil = System.nanoTime() + warmupMillis * 1_000_000
        do pass() while (System.nanoTime() < warmUntil)
        val nanos = ArrayList<Double>()
        val measureUntil = System.nanoTime() + measureMillis * 1_000_000
        while (nanos.size < MIN_RUNS || System.nanoTime() < measureUntil) {
            val start = System.nanoTime()
            pass()
            nanos += (System.nanoTime() - start).toDouble() / SAMPLES
        }
        nanos.sort()
        val median = if (nanos.size % 2 == 1) nanos[nanos.size / 2] else (nanos[nanos.size / 2 - 1] + nanos[nanos.size / 2]) / 2
        return SensorBenchmarkResult(name, median, nanos.first(), allocatedBytesPerSample(pass), SAMPLES, nanos.size)
    }

    /** Bytes this thread allocates per sample over one more pass, minus the counter's own cost. */
    private fun allocatedBytesPerSample(pass: () -> Unit): Double {
        val threads = ManagementFactory.getThreadMXBean() as? com.sun.management.ThreadMXBean ?: return -1.0
        if (!threads.isThreadAllocatedMemorySupported || !threads.isThreadAllocatedMemoryEnabled) return -1.0
        val thread = Thread.currentThread().id
        val overhead = (1..5).minOf { threads.getThreadAllocatedBytes(thread).let { before -> threads.getThreadAllocatedBytes(thread) - before } }
        val before = threads.getThreadAllocatedBytes(thread)
        pass()
        val allocated = threads.getThreadAllocatedBytes(thread) - before - overhead
        return allocated.coerceAtLeast(0L).toDouble() / SAMPLES
    }
}
