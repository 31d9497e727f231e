package org.hapticon.core.io

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
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
    public const val SCHEMA: String = HapticFormats.ICON_SCHEMA

    /** The schema version this build writes, and the newest it reads. */
    public const val VERSION: Int = HapticFormats.ICON_VERSION

    /** [icon] as a JSON object with members in schema order (whole numbers without a fraction). Does not throw. */
    public fun toJsonElement(icon: HapticIcon): JsonObject =
        SchemaJson.encodeToElement(IconDocument.serializer(), document(icon)) as JsonObject

    /**
     * The icon that [element] describes, for example one embedded in a message.
     *
     * Throws [IconValidationException] naming the field when [element] is not an object (field `icon`), when
     * `schema` is not [SCHEMA], when `version` is newer than [VERSION] ("unsupported icon schema version 2"),
     * or when a member is missing, of the wrong type, not finite, or out of range.
     */
    public fun fromJsonElement(element: JsonElement): HapticIcon {
        val doc = SchemaJson.decode(IconDocument.serializer(), element, IconReport)
        if (doc.count !in 1L..HapticIcon.MAX_COUNT.toLong()) fail("count", "must be in 1..${HapticIcon.MAX_COUNT}, was ${doc.count}")
        return HapticIcon(doc.name, doc.attack, doc.sustain, doc.level, doc.release, doc.note, doc.period, doc.count.toInt())
    }

    /** [icon] as JSON text: compact when [indent] is empty, else indented. Does not throw for a valid [indent]. */
    public fun encode(icon: HapticIcon, indent: String = ""): String = SchemaJson.encode(IconDocument.serializer(), document(icon), indent)

    /**
     * Parses one icon from [text].
     *
     * Throws [JsonException] when [text] is not valid JSON or exceeds [Json.DEFAULT_MAX_LENGTH], and
     * [IconValidationException] as [fromJsonElement] does.
     */
    public fun decode(text: String): HapticIcon = fromJsonElement(Json.decode(text))

    /** [icons] as a JSON array of icon objects. Does not throw for a valid [indent]. */
    public fun encodeList(icons: List<HapticIcon>, indent: String = ""): String =
        SchemaJson.encodeElement(JsonArray(icons.map(::toJsonElement)), indent)

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
        return value.mapIndexed { index, element ->
            try {
                fromJsonElement(element)
            } catch (e: IconValidationException) {
                val detail = e.message.orEmpty().removePrefix("${e.field}: ")
                throw IconValidationException("icons[$index].${e.field}", detail)
            }
        }
    }

    internal fun document(icon: HapticIcon): IconDocument = IconDocument(
        SCHEMA, VERSION.toLong(), icon.name, icon.attack, icon.sustain, icon.level, icon.release, icon.note, icon.period, icon.count.toLong(),
    )

    private fun fail(field: String, message: String): Nothing = throw IconValidationException(field, message)
}
