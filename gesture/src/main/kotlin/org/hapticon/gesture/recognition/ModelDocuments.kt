package org.hapticon.gesture.recognition

import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.doubleOrNull
import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.JsonKind
import org.hapticon.core.io.SchemaReport

/** A gesture model file, schema `hapticon.gesture-model` (docs/gesture-recognition.md); members in file order. */
@Serializable
internal class GestureModelDocument(
    val schema: String,
    val version: Int,
    val features: String,
    val sampleRate: Double,
    val channels: List<String>,
    val windowSeconds: Double,
    val hopSeconds: Double,
    val labels: List<String>,
    val forest: ForestDocument,
)

/** A [RandomForest]: counts and, per tree, parallel node arrays. */
@Serializable
internal class ForestDocument(val featureCount: Int, val classCount: Int, val trees: List<TreeDocument>)

/** One tree's node arrays (see `Tree`). */
@Serializable
internal class TreeDocument(val feature: IntArray, val threshold: DoubleArray, val left: IntArray, val right: IntArray)

/**
 * Model files' wording of schema problems, every one an [IllegalArgumentException] naming where: `model` for the
 * document and its forest, `trees[i]` for a tree. [header] checks `schema`, `version` and the feature set as soon
 * as each is read, so another kind of file is named as such before its other members are looked at.
 */
internal class ModelReport(private val header: (member: String, value: JsonElement) -> Unit = { _, _ -> }) : SchemaReport {
    override fun notAnObject(path: String, value: JsonElement): Nothing =
        throw IllegalArgumentException(if (path.isEmpty()) "model: expected a JSON object" else "${path.substringAfterLast('.')}: expected an object")

    override fun wrongType(path: String, member: String, expected: JsonKind, value: JsonElement?): Nothing {
        val where = where(path)
        val number = (value as? JsonPrimitive)?.takeUnless { it.isString }?.doubleOrNull
        throw IllegalArgumentException(
            when (expected) {
                JsonKind.OBJECT -> if (value == null) "$where: '$member' is missing" else "$member: expected an object"
                JsonKind.ARRAY -> "$where: '$member' must be an array"
                JsonKind.STRING -> "$where: '$member' must be a string"
                else -> when {
                    number == null -> "$where: '$member' must be a number"
                    !number.isFinite() -> "$where: '$member' must be finite"
                    else -> "$where: '$member' must be a whole number, was $number"
                }
            },
        )
    }

    override fun wrongElement(path: String, member: String, index: Int, expected: JsonKind, value: JsonElement): Nothing =
        throw IllegalArgumentException(
            "${where(path)}: '$member' must hold " + when (expected) {
                JsonKind.STRING -> "strings"
                JsonKind.NUMBER -> "finite numbers"
                else -> "whole numbers"
            },
        )

    override fun checked(path: String, member: String, value: JsonElement) {
        if (path.isEmpty()) header(member, value)
    }

    // The document and its forest are "model"; a tree is named by its index ("trees[3]").
    private fun where(path: String): String = if (path.isEmpty() || path == "forest") "model" else path.substringAfterLast('.')

    companion object {
        /** The text of a model file parsed strictly (at most [maxLength] characters), as a kotlinx tree. */
        fun parse(text: String, maxLength: Int = Json.DEFAULT_MAX_LENGTH): JsonElement = try {
            Json.decode(text, maxLength = maxLength)
        } catch (e: JsonException) {
            throw IllegalArgumentException("model is not valid JSON: ${e.message}")
        }

        /** The string content of a checked `schema`-like member. */
        fun text(value: JsonElement): String = (value as JsonPrimitive).content
    }
}
