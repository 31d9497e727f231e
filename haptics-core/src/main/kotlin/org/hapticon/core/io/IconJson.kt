package org.hapticon.core.io

import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException

/**
 * Icons as JSON, in the versioned schema
 * `{"schema": "hapticon.icon", "version": 1, "name": "knock", "attack": 0.005, "sustain": 0.01,
 * "level": 0.5, "release": 0.005, "note": 57, "period": 0.27, "count": 3}`.
 *
 * Decoding is strict about what it uses and lenient about the rest: `schema`, `version`, `name`,
 * `attack`, `sustain`, `level`, `release` and `note` are required, `period` defaults to 0 and `count`
 * to 1, and unknown members are ignored so that newer writers can add fields within version 1. Every
 * problem with a member is an [IconValidationException] whose [IconValidationException.field] names it,
 * for example `attack: expected a number, got "abc"`.
 */
public object IconJson {
    /** The value of the `schema` member. */
    public const val SCHEMA: String = "hapticon.icon"

    /** The schema version this build writes, and the newest it reads. */
    public const val VERSION: Int = 1

    /** [icon] as a JSON object with members in schema order. Does not throw. */
    public fun toJsonValue(icon: HapticIcon): JsonObject = JsonObject(
        linkedMapOf(
            "schema" to JsonString(SCHEMA),
            "version" to JsonNumber(VERSION),
            "name" to JsonString(icon.name),
            "attack" to JsonNumber(icon.attack),
            "sustain" to JsonNumber(icon.sustain),
            "level" to JsonNumber(icon.level),
            "release" to JsonNumber(icon.release),
            "note" to JsonNumber(icon.note),
            "period" to JsonNumber(icon.period),
            "count" to JsonNumber(icon.count),
        ),
    )

    /**
     * The icon that [value] describes, for example one embedded in a message.
     *
     * Throws [IconValidationException] naming the field when [value] is not an object (field `icon`), when
     * `schema` is not [SCHEMA], when `version` is newer than [VERSION] ("unsupported icon schema version 2"),
     * or when a member is missing, of the wrong type, not finite, or out of range.
     */
    public fun fromJsonValue(value: JsonValue): HapticIcon {
        if (value !is JsonObject) throw IconValidationException("icon", "expected an object, got ${snippet(value)}")
        // Schema and version come first: a newer document may have changed any other member.
        val schema = value["schema"] ?: fail("schema", "missing; expected \"$SCHEMA\"")
        if (schema != JsonString(SCHEMA)) fail("schema", "expected \"$SCHEMA\", got ${snippet(schema)}")
        val version = integer(value, "version") ?: fail("version", "missing")
        if (version != VERSION.toLong()) {
            fail("version", "unsupported icon schema version $version (this build reads version $VERSION)")
        }
        val count = integer(value, "count") ?: 1L
        if (count !in 1L..HapticIcon.MAX_COUNT.toLong()) fail("count", "must be in 1..${HapticIcon.MAX_COUNT}, was $count")
        return HapticIcon(
            name = string(value, "name") ?: fail("name", "missing"),
            attack = number(value, "attack") ?: fail("attack", "missing"),
            sustain = number(value, "sustain") ?: fail("sustain", "missing"),
            level = number(value, "level") ?: fail("level", "missing"),
            release = number(value, "release") ?: fail("release", "missing"),
            note = number(value, "note") ?: fail("note", "missing"),
            period = number(value, "period") ?: 0.0,
            count = count.toInt(),
        )
    }

    /** [icon] as JSON text: compact when [indent] is empty, else indented. Does not throw for a valid [indent]. */
    public fun encode(icon: HapticIcon, indent: String = ""): String = Json.encode(toJsonValue(icon), indent)

    /**
     * Parses one icon from [text].
     *
     * Throws [JsonException] when [text] is not valid JSON or exceeds [Json.DEFAULT_MAX_LENGTH], and
     * [IconValidationException] as [fromJsonValue] does.
     */
    public fun decode(text: String): HapticIcon = fromJsonValue(Json.decode(text))

    /** [icons] as a JSON array of icon objects. Does not throw for a valid [indent]. */
    public fun encodeList(icons: List<HapticIcon>, indent: String = ""): String =
        Json.encode(JsonArray(icons.map(::toJsonValue)), indent)

    /**
     * Parses a JSON array of icons from [text].
     *
     * Throws [JsonException] when [text] is not valid JSON, and [IconValidationException] when it is not an
     * array (field `icons`) or an element is invalid; the field then carries the element's index, for
     * example `icons[2].attack`.
     */
    public fun decodeList(text: String): List<HapticIcon> {
        val value = Json.decode(text)
        if (value !is JsonArray) throw IconValidationException("icons", "expected an array, got ${snippet(value)}")
        return value.elements.mapIndexed { index, element ->
            try {
                fromJsonValue(element)
            } catch (e: IconValidationException) {
                val detail = e.message.orEmpty().removePrefix("${e.field}: ")
                throw IconValidationException("icons[$index].${e.field}", detail)
            }
        }
    }

    private fun number(icon: JsonObject, field: String): Double? {
        val value = icon[field] ?: return null
        if (value !is JsonNumber) fail(field, "expected a number, got ${snippet(value)}")
        // JSON has no NaN or infinity, but 1e400 overflows a double to infinity.
        if (!value.value.isFinite()) fail(field, "expected a finite number, got ${snippet(value)}")
        return value.value
    }

    private fun integer(icon: JsonObject, field: String): Long? {
        val number = number(icon, field) ?: return null
        // 3.0 is accepted: many writers (JavaScript among them) do not distinguish it from 3.
        if (number != Math.rint(number)) fail(field, "expected an integer, got ${snippet(icon[field]!!)}")
        if (Math.abs(number) > 1e15) fail(field, "integer ${snippet(icon[field]!!)} is out of range")
        return number.toLong()
    }

    private fun string(icon: JsonObject, field: String): String? {
        val value = icon[field] ?: return null
        if (value !is JsonString) fail(field, "expected a string, got ${snippet(value)}")
        return value.value
    }

    private fun fail(field: String, message: String): Nothing = throw IconValidationException(field, message)
}
