package org.hapticon.companion.bench

import kotlinx.serialization.EncodeDefault
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.Serializable
import org.hapticon.core.io.ShortDouble

/**
 * What `hapticon bench --json` prints ([BenchReport.json]): every figure of a [BenchResult], rates in samples per
 * second, times in µs. Members come out in declaration order; a figure that was not measured (NaN, or negative where
 * the sensor benchmarks say so) is a null member left out. Numbers are spelled short ([ShortDouble]: `150`, not `150.0`).
 */
@Serializable
internal class BenchDocument(
    val sampleRate: Int,
    val blockSamples: Int,
    val throughput: List<ThroughputDocument>,
    @Serializable(with = ShortDouble::class) val fastMaxAbsError: Double,
    @Serializable(with = ShortDouble::class) val fastMaxAbsErrorDouble: Double,
    val fastErrorCases: List<ErrorCaseDocument>,
    val firstBlockSamples: Int,
    val firstBlockMicros: List<FirstBlockDocument>,
    val allocatedBytesPerBlock: AllocationDocument,
    val sensors: SensorsDocument,
    val targets: Map<String, TargetDocument>,
    @Serializable(with = ShortDouble::class) val elapsedSeconds: Double,
)

/** Min, median and max of a [Spread] and how many runs it has. */
@Serializable
internal class SpreadDocument(
    @Serializable(with = ShortDouble::class) val min: Double,
    @Serializable(with = ShortDouble::class) val median: Double,
    @Serializable(with = ShortDouble::class) val max: Double,
    val runs: Int,
)

@Serializable
internal class ThroughputDocument(
    val workload: String,
    val samples: Long,
    val sineLoop: SpreadDocument,
    val phasor: SpreadDocument,
    val exact: SpreadDocument,
    val fast: SpreadDocument,
    val exactVsSine: SpreadDocument,
    val fastVsPhasor: SpreadDocument,
)

@Serializable
internal class ErrorCaseDocument(
    val model: String,
    val sampleRate: Int,
    @Serializable(with = ShortDouble::class) val note: Double,
    val samples: Long,
    @Serializable(with = ShortDouble::class) val maxAbsError: Double,
    @Serializable(with = ShortDouble::class) val maxAbsErrorDouble: Double,
)

@Serializable
internal class FirstBlockDocument(
    val icon: String,
    @Serializable(with = ShortDouble::class) val exact: Double,
    @Serializable(with = ShortDouble::class) val fast: Double,
)

@Serializable
internal class AllocationDocument(
    @Serializable(with = ShortDouble::class) val exact: Double,
    @Serializable(with = ShortDouble::class) val fast: Double,
)

@OptIn(ExperimentalSerializationApi::class)
@Serializable
internal class TargetDocument(
    val goal: String,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val measured: Double? = null,
    val unit: String,
    val met: Boolean,
)

@Serializable
internal class SensorsDocument(
    val decode: List<DecodeDocument>,
    val models: List<ModelDocument>,
    val grainLatency: GrainLatencyDocument,
    val grainLatencyBaseline: GrainLatencyBaselineDocument,
)

@OptIn(ExperimentalSerializationApi::class)
@Serializable
internal class DecodeDocument(
    val protocol: String,
    val bytes: Long,
    val frames: Long,
    @Serializable(with = ShortDouble::class) val megabytesPerSecond: Double,
    val framesPerSecond: Long,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val allocatedBytesPerFrame: Double? = null,
)

@OptIn(ExperimentalSerializationApi::class)
@Serializable
internal class ModelDocument(
    val name: String,
    @Serializable(with = ShortDouble::class) val medianNanosPerSample: Double,
    @Serializable(with = ShortDouble::class) val bestNanosPerSample: Double,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val allocatedBytesPerSample: Double? = null,
    val samplesPerRun: Int,
    val runs: Int,
)

@OptIn(ExperimentalSerializationApi::class)
@Serializable
internal class GrainLatencyDocument(
    val samples: Int,
    val grains: Int,
    @Serializable(with = ShortDouble::class) val p50Micros: Double,
    @Serializable(with = ShortDouble::class) val p99Micros: Double,
    @Serializable(with = ShortDouble::class) val maxMicros: Double,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val runQueueMicrosAtMax: Double? = null,
    val gcAtMax: Boolean,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val maxWithoutRunQueueMicros: Double? = null,
    val over1ms: Int,
    val over1msByRunQueue: Int,
    val over1msWithGc: Int,
    val over1msBySafepoint: Int,
    val over1msByWaitAndSafepoint: Int,
    val over1msBySteal: Int,
    val over1msUnexplained: Int,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val safepoints: Int? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val longestSafepointMicros: Double? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val longestSafepoint: String? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val safepointMicrosAtMax: Double? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) val stealTicksAtMax: Long? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val stealPercent: Double? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val handlerAllocatedBytesPerSample: Double? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val readerAllocatedBytesPerSample: Double? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val readerCpuMicrosPerSample: Double? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val readerCpuShare: Double? = null,
)

@OptIn(ExperimentalSerializationApi::class)
@Serializable
internal class GrainLatencyBaselineDocument(
    val samples: Int,
    val grains: Int,
    @Serializable(with = ShortDouble::class) val p50Micros: Double,
    @Serializable(with = ShortDouble::class) val p99Micros: Double,
    @Serializable(with = ShortDouble::class) val maxMicros: Double,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val maxWithoutRunQueueMicros: Double? = null,
    @EncodeDefault(EncodeDefault.Mode.NEVER) @Serializable(with = ShortDouble::class) val handlerAllocatedBytesPerSample: Double? = null,
)
