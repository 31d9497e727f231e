package org.hapticon.companion.bench

import org.hapticon.sensor.grains.SensorBenchmarkResult
import org.hapticon.sensor.grains.SensorModelBenchmark

/**
 * The sensor figures of one bench run: decoding speed and allocation per protocol ([decode], from
 * [ProtocolBenchmark]), cost per sample of the grain decision and the handshake model ([models], from
 * [SensorModelBenchmark]), and the fake-port sample-to-grain-command [latency] through the real `GrainEngine`,
 * with [latencyBaseline], the engine's arithmetic re-created by hand, measured in the same run.
 */
data class SensorFigures(
    val decode: List<ProtocolBenchmark.Result>,
    val models: List<SensorBenchmarkResult>,
    val latency: GrainLatencyResult,
    val latencyBaseline: GrainLatencyResult,
) {
    /** The decoding result of [protocol] (`csv`, `framed` or `lucidgloves`). */
    fun decode(protocol: String): ProtocolBenchmark.Result = decode.first { it.name == protocol }

    /** The model result called [name] (`grainDecider` or `handshakePressure`). */
    fun model(name: String): SensorBenchmarkResult = models.first { it.name == name }
}

/** Runs the sensor measurements of `hapticon bench` as [config] says, reporting each step to [progress]. */
class SensorBench(private val config: BenchConfig, private val progress: (String) -> Unit = {}) {
    /** Decoding, models, then latency; about 6 s with [BenchConfig.FULL]. */
    fun run(): SensorFigures {
        progress("sensor decoding (csv, framed, lucidgloves)")
        val decode = ProtocolBenchmark.run(bufferBytes = config.decodeBufferBytes, runs = config.decodeRuns, warmupRuns = config.decodeWarmupRuns)
        progress("sensor models (grain decision, handshake pressure)")
        val models = SensorModelBenchmark.run(warmupMillis = config.modelWarmupMillis, measureMillis = config.modelMeasureMillis)
        progress("fake-port sample to grain command")
        val latency = GrainLatency(config.latencySamples, config.latencyWarmupSamples, GrainLatency.Route.ENGINE).run()
        val baseline = GrainLatency(config.latencySamples, config.latencyWarmupSamples, GrainLatency.Route.ARITHMETIC).run()
        return SensorFigures(decode, models, latency, baseline)
    }
}
