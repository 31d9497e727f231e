package org.hapticon.study.schema

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.doubleOrNull
import org.hapticon.core.io.JsonKind
import org.hapticon.core.io.SchemaReport

/**
 * The study formats' wording of schema problems: a [ProtocolException] whose path names the member, for example
 * `tasks[2].stimuli: expected an array, got 3` or `title: missing`. [what] names the document when it is not an
 * object. [headers] maps the path of each nested document to the schema it must declare (`""` → `hapticon.study`);
 * its `schema` and `version` are checked as soon as they are read, because a newer version may change anything.
 */
internal class StudyReport(private val what: String, private val headers: Map<String, Pair<String, Int>>) : SchemaReport {
    override fun notAnObject(path: String, value: JsonElement): Nothing =
        throw ProtocolException(path.ifEmpty { what }, "expected an object, got ${snippet(value)}")

    override fun wrongType(path: String, member: String, expected: JsonKind, value: JsonElement?): Nothing {
        val at = at(path, member)
        if (value == null) throw ProtocolException(at, "missing")
        val number = (value as? JsonPrimitive)?.takeUnless { it.isString }?.doubleOrNull
        if (expected == JsonKind.INT && number != null && number == Math.rint(number) && Math.abs(number) <= MAX_EXACT) {
            throw ProtocolException(at, "integer ${number.toLong()} is out of range")
        }
        throw ProtocolException(at, "expected ${article(expected)}, got ${snippet(value)}")
    }

    override fun wrongElement(path: String, member: String, index: Int, expected: JsonKind, value: JsonElement): Nothing =
        throw ProtocolException("${at(path, member)}[$index]", "expected ${article(expected)}, got ${snippet(value)}")

    override fun checked(path: String, member: String, value: JsonElement) {
        val (schema, version) = headers[path] ?: return
        if (member != "schema" && member != "version") return
        val found = (value as JsonPrimitive).content
        when (member) {
            "schema" -> if (found != schema) throw ProtocolException(at(path, member), "expected \"$schema\", got \"${found.take(40)}\"")
            "version" -> if (found != "$version") {
                throw ProtocolException(at(path, member), "unsupported $schema version $found (this build reads version $version)")
            }
        }
    }

    companion object {
        private const val MAX_EXACT = 9.007199254740992E15

        fun at(path: String, member: String): String = if (path.isEmpty()) member else "$path.$member"

        private fun article(kind: JsonKind): String = when (kind) {
            JsonKind.STRING -> "a string"
            JsonKind.INT, JsonKind.LONG -> "an integer"
            JsonKind.NUMBER -> "a number"
            JsonKind.BOOLEAN -> "a boolean"
            JsonKind.ARRAY -> "an array"
            JsonKind.OBJECT, JsonKind.ANY -> "an object"
        }

        /** [value] as short text for an error message. */
        fun snippet(value: JsonElement): String = when (value) {
            is JsonObject -> "an object"
            is JsonArray -> "an array"
            JsonNull -> "null"
            is JsonPrimitive -> if (value.isString) "\"${value.content.take(40)}${if (value.content.length > 40) "…" else ""}\"" else value.content
        }
    }
}
