package org.hapticon.core.io

import kotlinx.serialization.DeserializationStrategy
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.SerializationStrategy
import kotlinx.serialization.descriptors.PrimitiveKind
import kotlinx.serialization.descriptors.SerialDescriptor
import kotlinx.serialization.descriptors.StructureKind
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.JsonUnquotedLiteral
import kotlinx.serialization.json.Json as KotlinxJson
import kotlinx.serialization.json.JsonArray as KArray
import kotlinx.serialization.json.JsonNull as KNull
import kotlinx.serialization.json.JsonObject as KObject

/**
 * The bridge from our file and wire formats to kotlinx-serialization: each schema is a `@Serializable` type,
 * encoded by kotlinx-serialization; decoding goes text → [Json.decode] (the strict reader) → kotlinx
 * [JsonElement] → [check] against the type's [SerialDescriptor] → `decodeFromJsonElement`.
 *
 * Why the strict reader stays in front: kotlinx-serialization's parser keeps the last of duplicate member names
 * (`JsonTreeReader`: `result[key] = element`; Kotlin/kotlinx.serialization#1990 declined an option to refuse them)
 * and reports errors without a stable offset; our formats refuse duplicates, cap depth and length, and tests name
 * the offset. The reader builds kotlinx elements directly, so there is one tree type.
 *
 * Why [check] comes before kotlinx decoding: every format words its errors itself (`title: missing`,
 * `model: 'schema' must be a string`), and those messages are part of the format's contract (tests assert them);
 * kotlinx's own messages are neither stable across versions nor in our words. [check] walks the descriptor once,
 * so the schema is still declared only once, as the `@Serializable` type.
 */
public object SchemaJson {
    private val formats = HashMap<String, KotlinxJson>()

    /** The kotlinx format of our schemas: defaults written, unknown members ignored, strict otherwise. */
    public val format: KotlinxJson = KotlinxJson {
        encodeDefaults = true
        ignoreUnknownKeys = true
    }

    /**
     * [value] as JSON text: compact when [indent] is empty, otherwise one member or element per line, each level
     * indented by [indent]. Throws [IllegalArgumentException] when [indent] holds anything but spaces and tabs.
     */
    @OptIn(ExperimentalSerializationApi::class)
    public fun <T> encode(serializer: SerializationStrategy<T>, value: T, indent: String = ""): String {
        require(indent.all { it == ' ' || it == '\t' }) { "indent must be spaces or tabs only" }
        if (indent.isEmpty()) return format.encodeToString(serializer, value)
        val pretty = synchronized(formats) {
            formats.getOrPut(indent) {
                KotlinxJson(format) {
                    prettyPrint = true
                    prettyPrintIndent = indent
                }
            }
        }
        return pretty.encodeToString(serializer, value)
    }

    /**
     * Parses UTF-8 [bytes] with the strict reader ([Json.decodeUtf8]: size, depth, duplicate names, surrogates,
     * offsets) into a kotlinx tree. [allowTrailingCommas] accepts a comma before `]` or `}` (the same liberty as
     * kotlinx's `Json { allowTrailingComma = true }`), for AHAP files as Apple writes them. Throws [JsonException].
     */
    public fun parseUtf8(
        bytes: ByteArray,
        maxLength: Int = Json.DEFAULT_MAX_LENGTH,
        maxDepth: Int = Json.DEFAULT_MAX_DEPTH,
        allowTrailingCommas: Boolean = false,
    ): JsonElement = Json.decodeUtf8(bytes, maxLength, maxDepth, allowTrailingCommas)

    /** Parses [text] with the strict reader ([Json.decode]) into a kotlinx tree. Throws [JsonException]. */
    public fun parse(text: String, maxLength: Int = Json.DEFAULT_MAX_LENGTH, maxDepth: Int = Json.DEFAULT_MAX_DEPTH): JsonElement =
        Json.decode(text, maxLength, maxDepth)

    /** [element] as JSON text, compact or indented as [encode] writes it. */
    public fun encodeElement(element: JsonElement, indent: String = ""): String = encode(JsonElement.serializer(), element, indent)

    /** [value] as a kotlinx tree (members in schema order). */
    public fun <T> encodeToElement(serializer: SerializationStrategy<T>, value: T): JsonElement =
        format.encodeToJsonElement(serializer, value)

    /**
     * Decodes [element] as [deserializer] after [check]ing it; problems go to [report], which throws in the
     * format's own words. [path] is where [element] sits, for the messages (empty: it is the document).
     */
    public fun <T> decode(deserializer: DeserializationStrategy<T>, element: JsonElement, report: SchemaReport, path: String = ""): T =
        format.decodeFromJsonElement(deserializer, check(element, deserializer.descriptor, path, report))

    /**
     * Checks [element] against [descriptor] and returns it normalized for kotlinx decoding: whole numbers written
     * with a fraction (`3.0`, as JavaScript writes them) become integers where the schema wants one, and `null`
     * members the schema may omit are dropped so their defaults apply. [path] is where [element] sits
     * (`tasks[2].stimuli`, empty for the document). Throws whatever [report] throws at the first problem.
     */
    public fun check(element: JsonElement, descriptor: SerialDescriptor, path: String, report: SchemaReport): JsonElement {
        if (descriptor.kind != StructureKind.CLASS && descriptor.kind != StructureKind.OBJECT) return element
        val obj = element as? KObject ?: report.notAnObject(path, element)
        // Copied only when a member changes: nearly every document is already in normal form, and copying every
        // object cost more than the rest of the check (docs/json.md, "Speed of the chat codec").
        var out: LinkedHashMap<String, JsonElement>? = null
        for (i in 0 until descriptor.elementsCount) {
            val name = descriptor.getElementName(i)
            val child = descriptor.getElementDescriptor(i)
            val value = obj[name]
            if (value == null || value is KNull) {
                when {
                    value != null && child.isNullable -> {}
                    value != null && !report.nullMeansAbsent -> report.wrongType(path, name, kindOf(child), value)
                    descriptor.isElementOptional(i) -> if (value != null) (out ?: LinkedHashMap(obj).also { out = it }).remove(name)
                    else -> report.wrongType(path, name, kindOf(child), null)
                }
                continue
            }
            val checked = member(value, child, path, name, report)
            report.checked(path, name, checked)
            if (checked !== value) (out ?: LinkedHashMap(obj).also { out = it })[name] = checked
        }
        return out?.let(::KObject) ?: obj
    }

    private fun member(value: JsonElement, child: SerialDescriptor, path: String, name: String, report: SchemaReport): JsonElement {
        val at = if (path.isEmpty()) name else "$path.$name"
        val kind = kindOf(child)
        return when (kind) {
            JsonKind.ANY -> value
            JsonKind.OBJECT -> {
                if (value !is KObject) report.wrongType(path, name, kind, value)
                check(value, child, at, report)
            }
            JsonKind.ARRAY -> {
                val array = value as? KArray ?: report.wrongType(path, name, kind, value)
                val elementDescriptor = child.getElementDescriptor(0)
                val elementKind = kindOf(elementDescriptor)
                var changed = false
                val elements = array.mapIndexed { index, element ->
                    val checked = when (elementKind) {
                        JsonKind.OBJECT -> check(element, elementDescriptor, "$at[$index]", report)
                        JsonKind.ANY, JsonKind.ARRAY -> element
                        else -> primitive(element, elementKind) ?: report.wrongElement(path, name, index, elementKind, element)
                    }
                    if (checked !== element) changed = true
                    checked
                }
                if (changed) KArray(elements) else array
            }
            else -> primitive(value, kind) ?: report.wrongType(path, name, kind, value)
        }
    }

    /** [value] normalized for [kind], or null when it is not one. */
    private fun primitive(value: JsonElement, kind: JsonKind): JsonElement? {
        val p = value as? JsonPrimitive ?: return null
        if (p is KNull) return null
        return when (kind) {
            JsonKind.STRING -> p.takeIf { it.isString }
            JsonKind.BOOLEAN -> p.takeIf { !it.isString && (it.content == "true" || it.content == "false") }
            JsonKind.NUMBER -> p.takeIf { !it.isString && it.numberOrNull()?.isFinite() == true }
            JsonKind.INT, JsonKind.LONG -> {
                if (p.isString) return null
                // An integer within range and already spelled as the normal form below spells it (no '+', fraction,
                // exponent or "-0") is kept as it is: same value, no new primitive. Anything else takes the double path.
                val whole = p.content.toLongOrNull()
                if (whole != null && whole in (if (kind == JsonKind.INT) INT_RANGE else EXACT_RANGE) && isCanonicalInteger(p.content)) return p
                val limit = if (kind == JsonKind.INT) Int.MAX_VALUE.toDouble() else MAX_EXACT
                val d = p.numberOrNull()
                if (d == null || d != Math.rint(d) || Math.abs(d) > MAX_EXACT) return null
                if (d > limit || d < -limit - 1) null else JsonPrimitive(d.toLong())
            }
            else -> null
        }
    }

    private fun kindOf(descriptor: SerialDescriptor): JsonKind = when (descriptor.kind) {
        PrimitiveKind.STRING -> JsonKind.STRING
        PrimitiveKind.BOOLEAN -> JsonKind.BOOLEAN
        PrimitiveKind.INT, PrimitiveKind.SHORT, PrimitiveKind.BYTE -> JsonKind.INT
        PrimitiveKind.LONG -> JsonKind.LONG
        PrimitiveKind.DOUBLE, PrimitiveKind.FLOAT -> JsonKind.NUMBER
        StructureKind.LIST -> JsonKind.ARRAY
        StructureKind.CLASS, StructureKind.OBJECT -> JsonKind.OBJECT
        else -> JsonKind.ANY // JsonElement members, maps, polymorphic: the codec checks them itself
    }

    // Digits only, after an optional '-', without a leading zero (and not "-0", which kotlinx would read as 0 too,
    // but whose content the normalised form spells "0").
    private fun isCanonicalInteger(content: String): Boolean {
        val first = if (content.startsWith('-')) 1 else 0
        if (first == content.length) return false
        if (content[first] == '0') return content.length == 1
        for (i in first until content.length) if (content[i] !in '0'..'9') return false
        return true
    }

    private const val MAX_EXACT = 9.007199254740992E15
    private val INT_RANGE = Int.MIN_VALUE.toLong()..Int.MAX_VALUE.toLong()
    private val EXACT_RANGE = -(1L shl 53)..(1L shl 53) // what the double path accepts: |d| <= 2^53
}

/**
 * The number this primitive holds, or null when it holds none (a string, `true`, `false`, `null`): for a primitive
 * that is not a string, the same answer as kotlinx's `doubleOrNull`, at a fraction of its cost. `doubleOrNull` is Kotlin's `String.toDoubleOrNull`, which
 * screens the text with a regular expression before `java.lang.Double.parseDouble`; in the profile of a chat
 * message's decoding that screen was about a tenth of the time (docs/json.md, "Speed of the chat codec"). Here an
 * integer is read by `toLongOrNull` (no regular expression) and anything else by `parseDouble` itself, whose
 * grammar is the one the screen checks (it is written from `Double.valueOf`'s documentation), so the answers are
 * the same; the exception is only thrown for a value that is not a number, which is an error path. Does not throw.
 */
public fun JsonPrimitive.numberOrNull(): Double? {
    if (isString) return null
    val text = content
    val whole = text.toLongOrNull()
    if (whole != null) return if (whole == 0L && text.startsWith('-')) -0.0 else whole.toDouble()
    return try {
        java.lang.Double.parseDouble(text)
    } catch (e: NumberFormatException) {
        null
    }
}

/**
 * [value] as a JSON number spelled as our formats always spelled it: a whole number within ±2^53 without a
 * fraction (`57`, `-0`), anything else as [Double.toString] writes it (`0.27`, `7.8125E-4`), which kotlinx
 * writes unchanged. Keeps files and messages byte-identical to those of earlier builds. Throws
 * [IllegalArgumentException] for NaN or ±infinity (JSON has no spelling for them).
 */
@OptIn(ExperimentalSerializationApi::class)
public fun shortNumber(value: Double): JsonPrimitive {
    require(value.isFinite()) { "JSON cannot represent $value" }
    return when {
        value != Math.rint(value) || Math.abs(value) > 9.007199254740992E15 -> JsonPrimitive(value)
        value == 0.0 && 1.0 / value < 0 -> JsonUnquotedLiteral("-0")
        else -> JsonPrimitive(value.toLong())
    }
}

/** [value] as a JSON integer. Does not throw. */
public fun shortNumber(value: Long): JsonPrimitive = JsonPrimitive(value)

/** [value] as a JSON integer. Does not throw. */
public fun shortNumber(value: Int): JsonPrimitive = JsonPrimitive(value)

/** What a schema member holds, as [SchemaJson.check] sees it. */
public enum class JsonKind {
    /** A JSON string. */
    STRING,

    /** A finite JSON number. */
    NUMBER,

    /** A whole number within the range of `Int` (`3.0` counts). */
    INT,

    /** A whole number within ±2^53, where doubles are exact (`3.0` counts). */
    LONG,

    /** `true` or `false`. */
    BOOLEAN,

    /** A JSON array. */
    ARRAY,

    /** A JSON object. */
    OBJECT,

    /** Anything: the codec checks it. */
    ANY,
}

/** A format's wording of schema problems; every function throws the format's own exception. */
public interface SchemaReport {
    /**
     * Whether `null` for a member that cannot be null means "absent" (its default applies, or it is reported
     * missing), as most of our formats read it; false reports it as a wrong type. True by default.
     */
    public val nullMeansAbsent: Boolean get() = true

    /** [value], at [path] (empty: the document), should be an object. */
    public fun notAnObject(path: String, value: JsonElement): Nothing

    /** Member [member] of the object at [path] should be [expected]; [value] is null when it is missing. */
    public fun wrongType(path: String, member: String, expected: JsonKind, value: JsonElement?): Nothing

    /** Element [index] of array [member] of the object at [path] should be [expected]. */
    public fun wrongElement(path: String, member: String, index: Int, expected: JsonKind, value: JsonElement): Nothing

    /**
     * Member [member] of the object at [path] has the right shape ([value], normalized); members are checked in
     * schema order, so a format checks values that decide how to read the rest (`schema`, `version`) here,
     * before later members are looked at. Does nothing by default.
     */
    public fun checked(path: String, member: String, value: JsonElement) {}
}
