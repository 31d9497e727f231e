package org.hapticon.core.io

/**
 * A JSON value: [JsonObject], [JsonArray], [JsonString], [JsonNumber], [JsonBoolean] or [JsonNull].
 *
 * Values are immutable. [Json.decode] produces them and [Json.encode] writes them.
 */
public sealed interface JsonValue

/**
 * A JSON object whose members keep their insertion order (the order they had in the text).
 *
 * The public constructor copies its argument, so later changes to it do not show through (the parser,
 * whose maps nobody else holds, skips the copy). Two objects are equal when they have equal members,
 * regardless of order.
 */
public class JsonObject internal constructor(
    /** The members in insertion order. */
    public val members: Map<String, JsonValue>,
    @Suppress("UNUSED_PARAMETER") owned: Boolean,
) : JsonValue {
    /** Makes an object of [members] in their iteration order. Does not throw. */
    public constructor(members: Map<String, JsonValue>) : this(LinkedHashMap(members), owned = true)

    /** The value of the member called [name], or null when there is no such member. */
    public operator fun get(name: String): JsonValue? = members[name]

    /** Compares members; order is not significant. */
    override fun equals(other: Any?): Boolean = other is JsonObject && members == other.members

    /** Hash of the members. */
    override fun hashCode(): Int = members.hashCode()

    /** A debug representation, for example `JsonObject({a=JsonNull})`. */
    override fun toString(): String = "JsonObject($members)"
}

/**
 * A JSON array. The public constructor copies its argument, so later changes to it do not show through (the
 * parser, whose lists nobody else holds, skips the copy).
 */
public class JsonArray internal constructor(
    /** The elements in order. */
    public val elements: List<JsonValue>,
    @Suppress("UNUSED_PARAMETER") owned: Boolean,
) : JsonValue {
    /** Makes an array of [elements]. Does not throw. */
    public constructor(elements: List<JsonValue>) : this(elements.toList(), owned = true)

    /** Number of elements. */
    public val size: Int get() = elements.size

    /** The element at [index]; throws [IndexOutOfBoundsException] when there is none. */
    public operator fun get(index: Int): JsonValue = elements[index]

    /** Compares elements in order. */
    override fun equals(other: Any?): Boolean = other is JsonArray && elements == other.elements

    /** Hash of the elements. */
    override fun hashCode(): Int = elements.hashCode()

    /** A debug representation, for example `JsonArray([JsonNull])`. */
    override fun toString(): String = "JsonArray($elements)"
}

/**
 * A JSON string.
 *
 * @property value the decoded text, escapes resolved.
 */
public data class JsonString(val value: String) : JsonValue

/**
 * A JSON number.
 *
 * [isIntegral] records the written form: true for a literal without fraction or exponent (`3`),
 * false otherwise (`3.0`, `3e0`). [Json.encode] writes integral numbers without a fraction, so the form
 * survives a round trip. The default is true exactly when [value] is a whole number within ±2^53 (where
 * doubles are exact integers), which makes `JsonNumber(57.0)` encode as `57`.
 *
 * [value] may be infinite: an integer or exponent too large for a double (`1e400`) decodes to ±infinity,
 * so that a caller can report the field by name. [Json.encode] rejects non-finite numbers.
 *
 * Throws [IllegalArgumentException] when [value] is NaN, or when [isIntegral] is true for a value with a
 * fraction.
 *
 * @property value the number; ±infinity only for overflowing literals.
 * @property isIntegral whether it is written without fraction or exponent.
 */
public data class JsonNumber(val value: Double, val isIntegral: Boolean = isExactInteger(value)) : JsonValue {
    init {
        require(!value.isNaN()) { "a JSON number cannot be NaN" }
        require(!isIntegral || value == Math.rint(value)) { "$value is not integral" }
    }

    /** Makes an integral number; values beyond ±2^53 lose precision, as any double does. */
    public constructor(value: Long) : this(value.toDouble(), isIntegral = true)

    /** Makes an integral number. */
    public constructor(value: Int) : this(value.toDouble(), isIntegral = true)
}

/**
 * A JSON `true` or `false`.
 *
 * @property value the boolean.
 */
public data class JsonBoolean(val value: Boolean) : JsonValue

/** The JSON `null`. */
public data object JsonNull : JsonValue

private fun isExactInteger(value: Double): Boolean = Math.abs(value) <= 9.007199254740992E15 && value == Math.rint(value)
