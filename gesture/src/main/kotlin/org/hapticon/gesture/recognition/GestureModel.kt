package org.hapticon.gesture.recognition

import org.hapticon.gesture.GestureFormats
import org.hapticon.core.io.SchemaJson
import org.hapticon.gesture.Recording
import kotlin.math.abs
import kotlin.math.roundToInt

/** The sliding window a model classifies: [windowSeconds] long, a new decision every [hopSeconds]. */
public class WindowConfig(
    public val windowSeconds: Double = DEFAULT_WINDOW_SECONDS,
    public val hopSeconds: Double = DEFAULT_HOP_SECONDS,
) {
    init {
        require(windowSeconds.isFinite() && windowSeconds > 0.0 && windowSeconds <= MAX_WINDOW_SECONDS) {
            "window must be in (0, $MAX_WINDOW_SECONDS] s, was $windowSeconds"
        }
        require(hopSeconds.isFinite() && hopSeconds > 0.0 && hopSeconds <= windowSeconds) { "hop must be in (0, window] s, was $hopSeconds" }
    }

    /** Window length in frames at [sampleRate] (at least 1). */
    public fun windowFrames(sampleRate: Double): Int = (windowSeconds * sampleRate).roundToInt().coerceAtLeast(1)

    /** Hop in frames at [sampleRate] (at least 1). */
    public fun hopFrames(sampleRate: Double): Int = (hopSeconds * sampleRate).roundToInt().coerceAtLeast(1)

    override fun toString(): String = "WindowConfig(window=${windowSeconds}s, hop=${hopSeconds}s)"

    public companion object {
        /** The default window, chosen from `hapticon classify-bench` (docs/gesture-recognition.md). */
        public const val DEFAULT_WINDOW_SECONDS: Double = 1.0

        /** The default hop: ten decisions a second. */
        public const val DEFAULT_HOP_SECONDS: Double = 0.1

        /** Longest window accepted: longer ones only add latency. */
        public const val MAX_WINDOW_SECONDS: Double = 10.0
    }
}

/**
 * A trained gesture recogniser: a [forest] over the [WindowFeatures] of [channels] (in this order) sampled at
 * [sampleRate] Hz in windows of [window], whose classes are [labels]. It carries its configuration so that a
 * model trained on a laptop and loaded on a phone classifies exactly the same way, and [requireMatches]
 * refuses data it was not trained for.
 */
public class GestureModel(
    public val sampleRate: Double,
    public val channels: List<String>,
    public val window: WindowConfig,
    public val labels: List<GestureLabel>,
    public val forest: RandomForest,
) {
    init {
        require(sampleRate.isFinite() && sampleRate > 0.0) { "sample rate must be finite and > 0 Hz, was $sampleRate" }
        require(channels.isNotEmpty() && channels.toSet().size == channels.size) { "channels must be non-empty and unique, were $channels" }
        require(labels.isNotEmpty() && labels.toSet().size == labels.size) { "labels must be non-empty and unique, were $labels" }
        require(forest.classCount == labels.size) { "forest has ${forest.classCount} classes for ${labels.size} labels" }
        require(forest.featureCount == channels.size * WindowFeatures.PER_CHANNEL) {
            "forest expects ${forest.featureCount} features, ${channels.size} channels give ${channels.size * WindowFeatures.PER_CHANNEL}"
        }
    }

    /** Frames per window. */
    public val windowFrames: Int get() = window.windowFrames(sampleRate)

    /** Frames per hop. */
    public val hopFrames: Int get() = window.hopFrames(sampleRate)

    /**
     * Throws [IllegalArgumentException] saying what differs unless [recording] has this model's channels
     * (same names, same order; extra channels are not allowed) and sample rate (within 0.1 %).
     */
    public fun requireMatches(recording: Recording) {
        requireMatches(recording.channels.map { it.name }, recording.sampleRate)
    }

    /** As [requireMatches] for a stream of [channelNames] at [rate] Hz. */
    public fun requireMatches(channelNames: List<String>, rate: Double) {
        require(channelNames == channels) { "model expects channels $channels, got $channelNames" }
        require(abs(rate - sampleRate) <= sampleRate * 1e-3) { "model expects $sampleRate Hz, got $rate Hz" }
    }

    /** A new [WindowClassifier] (with its own scratch arrays) for this model. */
    public fun classifier(): WindowClassifier = WindowClassifier(this)

    /** This model as JSON text in schema [SCHEMA] version [VERSION]. */
    public fun encode(): String = SchemaJson.encode(
        GestureModelDocument.serializer(),
        GestureModelDocument(
            SCHEMA, VERSION, FEATURE_SET, sampleRate, channels, window.windowSeconds, window.hopSeconds,
            labels.map { it.id }, forest.toDocument(),
        ),
    )

    override fun toString(): String =
        "GestureModel($channels at $sampleRate Hz, $window, ${labels.size} labels, ${forest.treeCount} trees)"

    public companion object {
        /** The `schema` member of a model file ([GestureFormats.GESTURE_MODEL_SCHEMA]). */
        public const val SCHEMA: String = GestureFormats.GESTURE_MODEL_SCHEMA

        /** The version this build writes and reads ([GestureFormats.GESTURE_MODEL_VERSION]). */
        public const val VERSION: Int = GestureFormats.GESTURE_MODEL_VERSION

        /** Names the feature definition ([WindowFeatures]); a model with another set is refused. */
        public const val FEATURE_SET: String = "stats33-v1"

        /** Largest model text accepted by [decode]: 64 MiB (a 100-tree forest is a few MiB). */
        public const val MAX_MODEL_CHARS: Int = 64 shl 20

        /**
         * The model [text] (written by [encode]) describes. [IllegalArgumentException] naming the problem when
         * it is not JSON, another schema, version or feature set, or malformed.
         */
        public fun decode(text: String): GestureModel {
            val report = ModelReport { member, value ->
                when (member) {
                    "schema" -> ModelReport.text(value).let { require(it == SCHEMA) { "model: schema must be \"$SCHEMA\", was \"$it\"" } }
                    "version" -> ModelReport.text(value).let { require(it == "$VERSION") { "model: unsupported version $it (this build reads $VERSION)" } }
                    "features" -> ModelReport.text(value).let { require(it == FEATURE_SET) { "model: feature set \"$it\" is not \"$FEATURE_SET\"" } }
                }
            }
            val doc = SchemaJson.decode(GestureModelDocument.serializer(), ModelReport.parse(text, MAX_MODEL_CHARS), report)
            val window = WindowConfig(doc.windowSeconds, doc.hopSeconds)
            val labels = doc.labels.map { GestureLabel.parse(it) }
            return GestureModel(doc.sampleRate, doc.channels, window, labels, RandomForest.fromDocument(doc.forest))
        }
    }
}

/**
 * Classifies windows for one [model], reusing its feature and probability arrays: after [classify],
 * [probabilities] holds the vote share of each of the model's labels. Not thread-safe; allocates nothing per call.
 */
public class WindowClassifier(public val model: GestureModel) {
    private val extractor = WindowFeatures(model.sampleRate, model.windowFrames)
    private val features = DoubleArray(model.forest.featureCount)

    /** Vote share per label of the last [classify], in [GestureModel.labels] order. */
    public val probabilities: DoubleArray = DoubleArray(model.labels.size)

    /**
     * The label of the window of [GestureModel.windowFrames] frames starting at [from] in [channels] (one array
     * per model channel, in model order).
     */
    public fun classify(channels: List<DoubleArray>, from: Int): GestureLabel {
        require(channels.size == model.channels.size) { "expected ${model.channels.size} channels, got ${channels.size}" }
        val frames = model.windowFrames
        for (i in channels.indices) extractor.extract(channels[i], from, frames, features, i * WindowFeatures.PER_CHANNEL)
        return model.labels[model.forest.predict(features, probabilities)]
    }
}
