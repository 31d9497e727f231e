package org.hapticon.gesture.social

import org.hapticon.gesture.GestureFormats
import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonArray
import org.hapticon.core.io.SchemaJson
import org.hapticon.gesture.recognition.ModelReport

/**
 * A trained social-touch classifier: [boost] over the [SocialTouchFeatures] of a whole message, whose classes are
 * [labels] (whatever the training data named: the paper's six emotions, six social messages and no touch, or a
 * researcher's own set).
 */
public class SocialTouchModel(public val labels: List<String>, public val boost: LogitBoost) {
    init {
        require(labels.size == boost.classCount && labels.toSet().size == labels.size) { "need ${boost.classCount} distinct labels, got $labels" }
        require(boost.featureCount == SocialTouchFeatures.COUNT) { "expected ${SocialTouchFeatures.COUNT} features, got ${boost.featureCount}" }
    }

    /** The label of a message with [features], and its probability. */
    public fun classify(features: DoubleArray): Pair<String, Double> {
        val p = DoubleArray(labels.size)
        val best = boost.predict(features, p)
        return labels[best] to p[best]
    }

    /** This model as JSON in schema [SCHEMA] version [VERSION]. */
    public fun encode(): String {
        val stumps = boost.flatStumps()
        return SchemaJson.encode(
            SocialTouchDocument.serializer(),
            SocialTouchDocument(
                SCHEMA, VERSION, SocialTouchFeatures.NAMES, labels,
                IntArray(stumps.size) { stumps[it].feature }, DoubleArray(stumps.size) { stumps[it].threshold },
                DoubleArray(stumps.size) { stumps[it].left }, DoubleArray(stumps.size) { stumps[it].right },
            ),
        )
    }

    public companion object {
        /** The `schema` member of a model file ([GestureFormats.SOCIAL_TOUCH_MODEL_SCHEMA]). */
        public const val SCHEMA: String = GestureFormats.SOCIAL_TOUCH_MODEL_SCHEMA

        /** The version this build writes and reads ([GestureFormats.SOCIAL_TOUCH_MODEL_VERSION]). */
        public const val VERSION: Int = GestureFormats.SOCIAL_TOUCH_MODEL_VERSION

        /** Whether [text] looks like a social-touch model (its schema member), without parsing the rest. */
        public fun isSocialTouchModel(text: String): Boolean = text.contains("\"$SCHEMA\"")

        /** The model [text] describes; [IllegalArgumentException] naming the problem. */
        public fun decode(text: String): SocialTouchModel {
            val report = ModelReport { member, value ->
                when (member) {
                    "schema" -> require(ModelReport.text(value) == SCHEMA) { "model: schema must be \"$SCHEMA\"" }
                    "version" -> require(ModelReport.text(value) == "$VERSION") { "model: unsupported version (this build reads $VERSION)" }
                    "features" -> require((value as JsonArray).map { ModelReport.text(it) } == SocialTouchFeatures.NAMES) {
                        "model: feature set differs from ${SocialTouchFeatures.NAMES}"
                    }
                }
            }
            val doc = SchemaJson.decode(SocialTouchDocument.serializer(), ModelReport.parse(text), report)
            val labels = doc.labels
            val feature = doc.feature
            val threshold = doc.threshold
            val left = doc.left
            val right = doc.right
            require(setOf(feature.size, threshold.size, left.size, right.size).size == 1) { "model: stump arrays differ in length" }
            require(labels.size >= 2) { "model: need at least 2 labels" }
            val stumps = feature.indices.map { Stump(feature[it], threshold[it], left[it], right[it]) }
            return SocialTouchModel(labels, LogitBoost.of(SocialTouchFeatures.COUNT, labels.size, stumps))
        }
    }
}

/** A social-touch model file, schema `hapticon.social-touch-model`: the boosted stumps as parallel arrays. */
@Serializable
internal class SocialTouchDocument(
    val schema: String,
    val version: Int,
    val features: List<String>,
    val labels: List<String>,
    val feature: IntArray,
    val threshold: DoubleArray,
    val left: DoubleArray,
    val right: DoubleArray,
)

/**
 * A contact stream as CSV: header `time_s,intensity,x,y,area`, one [ContactFrame] per line (a touchscreen's or one
 * pressure sensor's recording). Errors are [IllegalArgumentException]s naming [source] and the line.
 */
public object ContactCsv {
    /** The header. */
    public const val HEADER: String = "time_s,intensity,x,y,area"

    /** The frames of [text]. */
    public fun read(text: String, source: String): List<ContactFrame> {
        val lines = dataLines(text)
        require(lines.isNotEmpty() && lines[0].value.trim().replace(" ", "") == HEADER) {
            "$source:${lines.firstOrNull()?.index?.plus(1) ?: 1}: expected the header $HEADER"
        }
        return lines.drop(1).map { (i, line) ->
            val cells = line.split(',').map { it.trim().toDoubleOrNull() }
            require(cells.size == 5 && cells.all { it != null && it.isFinite() }) { "$source:${i + 1}: expected 5 finite numbers, got \"$line\"" }
            ContactFrame(cells[0]!!, cells[1]!!, cells[2]!!, cells[3]!!, cells[4]!!)
        }
    }

    internal fun dataLines(text: String) = text.lineSequence().withIndex().filter { it.value.isNotBlank() && !it.value.startsWith("#") }.toList()
}

/** A skin's recording: its [layout] and its [frames] in time order. */
public class SkinRecording(public val layout: SkinLayout, public val frames: List<SkinFrame>)

/**
 * A skin recording as CSV: header `time_s,joint,e:X:Y,…` — one column per element, named by its centroid (X, Y) — and
 * one [SkinFrame] per line: time, the joint sensor's change (0 without one) and every element's intensity. An EIT skin
 * exports its reconstructed images this way, a pressure grid its cells.
 */
public object SkinCsv {
    /** The first two header cells. */
    public const val HEADER_START: String = "time_s,joint"

    /** Whether [text]'s header is a skin recording's. */
    public fun isSkin(text: String): Boolean =
        ContactCsv.dataLines(text).firstOrNull()?.value?.replace(" ", "")?.startsWith("$HEADER_START,e:") == true

    /** The recording in [text]; [IllegalArgumentException] naming [source] and the line. */
    public fun read(text: String, source: String): SkinRecording {
        val lines = ContactCsv.dataLines(text)
        val headerLine = lines.firstOrNull()
        val header = headerLine?.value?.replace(" ", "")?.split(',').orEmpty()
        val at = "$source:${headerLine?.index?.plus(1) ?: 1}"
        require(header.size >= 3 && header[0] == "time_s" && header[1] == "joint") { "$at: expected the header $HEADER_START,e:X:Y,..." }
        val xs = DoubleArray(header.size - 2)
        val ys = DoubleArray(header.size - 2)
        for (k in 2 until header.size) {
            val parts = header[k].split(':')
            val x = parts.getOrNull(1)?.toDoubleOrNull()
            val y = parts.getOrNull(2)?.toDoubleOrNull()
            require(parts.size == 3 && parts[0] == "e" && x != null && y != null && x.isFinite() && y.isFinite()) {
                "$at: column ${k + 1} must be e:X:Y (an element and its centroid), got \"${header[k]}\""
            }
            xs[k - 2] = x
            ys[k - 2] = y
        }
        val frames = lines.drop(1).map { (i, line) ->
            val cells = line.split(',').map { it.trim().toDoubleOrNull() }
            require(cells.size == header.size && cells.all { it != null && it.isFinite() }) {
                "$source:${i + 1}: expected ${header.size} finite numbers, got ${cells.size}"
            }
            SkinFrame(cells[0]!!, DoubleArray(xs.size) { cells[it + 2]!! }, cells[1]!!)
        }
        return SkinRecording(SkinLayout(xs, ys), frames)
    }

    /** [recording] as CSV text. */
    public fun write(recording: SkinRecording): String = buildString {
        append(HEADER_START)
        for (k in 0 until recording.layout.size) append(",e:").append(recording.layout.x(k)).append(':').append(recording.layout.y(k))
        append('\n')
        for (f in recording.frames) {
            append(f.timeSeconds).append(',').append(f.joint)
            for (v in f.elements) append(',').append(v)
            append('\n')
        }
    }
}

/** One touch message read from a file: its [features], its number of [touches] and [seconds] from first to last contact. */
public class MessageFile(public val features: DoubleArray, public val touches: Int, public val seconds: Double)

/**
 * A message file of either kind as the 13 [SocialTouchFeatures]: a [SkinCsv] recording on its own layout, cut by
 * [TouchThresholds.DEFAULT]; a [ContactCsv] stream drawn on a [TouchPadSkin] and cut at any contact.
 */
public object MessageFiles {
    /** The features of [text]; [IllegalArgumentException] naming [source] and the line. */
    public fun read(text: String, source: String): MessageFile {
        val features = if (SkinCsv.isSkin(text)) {
            val recording = SkinCsv.read(text, source)
            SocialTouchFeatures(recording.layout).also { f -> recording.frames.forEach(f::offer) }
        } else {
            val pad = TouchPadSkin()
            SocialTouchFeatures(pad.layout, TouchThresholds.ANY_CONTACT).also { f -> ContactCsv.read(text, source).forEach { f.offer(pad.frame(it)) } }
        }
        return MessageFile(features.features(), features.touchCount, features.contactSeconds)
    }
}
