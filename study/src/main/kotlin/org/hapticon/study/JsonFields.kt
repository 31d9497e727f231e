package org.hapticon.study

import org.hapticon.core.io.JsonArray
import org.hapticon.core.io.JsonBoolean
import org.hapticon.core.io.JsonNull
import org.hapticon.core.io.JsonNumber
import org.hapticon.core.io.JsonObject
import org.hapticon.core.io.JsonString
import org.hapticon.core.io.JsonValue

/**
 * Typed, path-aware access to the members of one JSON object: every problem is a [ProtocolException] whose path
 * is [path] plus the member, for example `tasks[2].stimuli` (an empty [path] means the document itself).
 * Unknown members are ignored, so that newer writers can add fields within a schema version.
 */
internal class JsonFields(private val json: JsonObject, private val path: String) {
    fun at(member: String): String = if (path.isEmpty()) member else "$path.$member"

    fun optional(member: String): JsonValue? = json[member]?.takeUnless { it == JsonNull }

    fun string(member: String): String = optionalString(member) ?: missing(member)

    fun optionalString(member: String): String? {
        val value = optional(member) ?: return null
        return (value as? JsonString)?.value ?: wrongType(member, "a string", value)
    }

    fun long(member: String): Long = optionalLong(member) ?: missing(member)

    fun optionalLong(member: String): Long? {
        val value = optional(member) ?: return null
        val number = (value as? JsonNumber)?.value ?: wrongType(member, "an integer", value)
        // 3.0 is accepted: JavaScript writers do not distinguish it from 3. Beyond 2^53 doubles are not exact.
        if (!number.isFinite() || number != Math.rint(number) || Math.abs(number) > MAX_EXACT) {
            throw ProtocolException(at(member), "expected an integer, got ${snippet(value)}")
        }
        return number.toLong()
    }

    fun int(member: String): Int = optionalInt(member) ?: missing(member)

    fun optionalInt(member: String): Int? {
        val value = optionalLong(member) ?: return null
        if (value !in Int.MIN_VALUE..Int.MAX_VALUE) throw ProtocolException(at(member), "integer $value is out of range")
        return value.toInt()
    }

    fun obj(member: String): JsonFields {
        val value = optional(member) ?: missing(member)
        return JsonFields(value as? JsonObject ?: wrongType(member, "an object", value), at(member))
    }

    fun array(member: String): List<JsonValue> = optionalArray(member) ?: missing(member)

    fun optionalArray(member: String): List<JsonValue>? {
        val value = optional(member) ?: return null
        return (value as? JsonArray)?.elements ?: wrongType(member, "an array", value)
    }

    /** The elements of array [member] as objects, each checked and handed to [read] with its own path. */
    fun <T> objects(member: String, read: (JsonFields) -> T): List<T> = array(member).mapIndexed { i, element ->
        read(JsonFields(element as? JsonObject ?: throw ProtocolException("${at(member)}[$i]", "expected an object, got ${snippet(element)}"), "${at(member)}[$i]"))
    }

    /** The elements of array [member] as strings. */
    fun strings(member: String): List<String>? = optionalArray(member)?.mapIndexed { i, element ->
        (element as? JsonString)?.value ?: throw ProtocolException("${at(member)}[$i]", "expected a string, got ${snippet(element)}")
    }

    /** Fails unless `schema` is [schema] and `version` is at most [version]; checked first, as a newer document may change anything. */
    fun requireSchema(schema: String, version: Int) {
        val found = optionalString("schema") ?: missing("schema")
        if (found != schema) throw ProtocolException(at("schema"), "expected \"$schema\", got \"${found.take(40)}\"")
        val v = long("version")
        if (v != version.toLong()) throw ProtocolException(at("version"), "unsupported $schema version $v (this build reads version $version)")
    }

    fun missing(member: String): Nothing = throw ProtocolException(at(member), "missing")

    private fun wrongType(member: String, expected: String, value: JsonValue): Nothing =
        throw ProtocolException(at(member), "expected $expected, got ${snippet(value)}")

    companion object {
        private const val MAX_EXACT = 9.007199254740992E15

        /** Fields of [value], which must be an object; [what] names it in the error. */
        fun of(value: JsonValue, path: String, what: String): JsonFields =
            JsonFields(value as? JsonObject ?: throw ProtocolException(path.ifEmpty { what }, "expected an object, got ${snippet(value)}"), path)

        fun snippet(value: JsonValue): String = when (value) {
            is JsonString -> "\"${value.value.take(40)}${if (value.value.length > 40) "…" else ""}\""
            is JsonNumber -> if (value.isIntegral) value.value.toLong().toString() else value.value.toString()
            is JsonObject -> "an object"
            is JsonArray -> "an array"
            is JsonBoolean -> value.value.toString()
            JsonNull -> "null"
        }
    }
}
