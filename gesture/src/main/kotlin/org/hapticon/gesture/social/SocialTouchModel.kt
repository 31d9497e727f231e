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
 * A contact stream as CSV: header `time_s,intensity,x,y,area`, one frame per line (see [ContactFrame]). Errors are
 * [IllegalArgumentException]s naming [source] and the line.
 */
public object ContactCsv {
    /** The header. */
    public const val HEADER: String = "time_s,intensity,x,y,area"

    /** The frames of [text]. */
    public fun read(text: String, source: String): List<ContactFrame> {
        val lines = text.lineSequence().withIndex().filter { it.value.isNotBlank() && !it.value.startsWith("#") }.toList()
        require(lines.isNotEmpty() && lines[0].value.trim().replace(" ", "") == HEADER) {
            "$source:${lines.firstOrNull()?.index?.plus(1) ?: 1}: expected the header $HEADER"
        }
        return lines.drop(1).map { (i, line) ->
            val cells = line.split(',').map { it.trim().toDoubleOrNull() }
            require(cells.size == 5 && cells.all { it != null && it.isFinite() }) { "$source:${i + 1}: expected 5 finite numbers, got \"$line\"" }
            ContactFrame(cells[0]!!, cells[1]!!, cells[2]!!, cells[3]!!, cells[4]!!)
        }
    }
}
