package org.hapticon.core.pattern

import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.IconValidationException
import org.hapticon.core.io.HapticFormats
import org.hapticon.core.io.IconJson
import org.hapticon.core.io.JsonKind
import org.hapticon.core.io.SchemaJson
import org.hapticon.core.io.SchemaReport
import org.hapticon.core.io.ShortDouble
import org.hapticon.core.io.snippet

/**
 * Patterns as Hapticon JSON: `{"schema": "hapticon.pattern", "version": 1, "name": "boing",
 * "amplitude": [{"time": 0, "amplitude": 0.64}, …], "frequency": [{"time": 0, "hertz": 180}],
 * "transients": [{"time": 0, "intensity": 0.8, "sharpness": 0.4}]}` — the pattern's own fields, nothing
 * lost. `transients` may be omitted. [read] also takes an icon (`"schema": "hapticon.icon"`, [IconJson]) and
 * returns it as a pattern, so every command that takes a pattern takes an icon file too.
 *
 * The schema is the `@Serializable` [PatternDocument], encoded by kotlinx-serialization and checked by
 * [SchemaJson.check] with this format's wording (docs/json.md).
 */
public object PatternJson {
    /** The value of the `schema` member ([HapticFormats.PATTERN_SCHEMA]). */
    public const val SCHEMA: String = HapticFormats.PATTERN_SCHEMA

    /** The schema version this build writes, and the newest it reads ([HapticFormats.PATTERN_VERSION]). */
    public const val VERSION: Int = HapticFormats.PATTERN_VERSION

    /** [pattern] as a kotlinx JSON object, members in schema order, whole numbers without a fraction. Does not throw. */
    public fun toJsonElement(pattern: HapticPattern): JsonObject =
        SchemaJson.encodeToElement(PatternDocument.serializer(), document(pattern)) as JsonObject

    /** [pattern] as the text of a pattern file: indented by [indent] (compact when empty). Does not throw for a valid [indent]. */
    public fun encode(pattern: HapticPattern, indent: String = "  "): String =
        SchemaJson.encode(PatternDocument.serializer(), document(pattern), indent)

    /**
     * The pattern [value] describes: a pattern document, or an icon document converted by [toPattern] (with a
     * note saying so). Throws [PatternException] naming the member for anything malformed or out of range.
     */
    public fun read(value: JsonElement): PatternImport {
        val root = value as? JsonObject ?: throw PatternException("pattern", "expected an object, got ${snippet(value)}")
        val schema = root["schema"]
        if (schema is JsonPrimitive && schema.isString && schema.content == IconJson.SCHEMA) {
            val icon = try {
                IconJson.fromJsonElement(root)
            } catch (e: IconValidationException) {
                throw PatternException(e.field, e.message!!.removePrefix("${e.field}: "))
            }
            return PatternImport(icon.toPattern(), listOf("icon '${icon.name}' became a pattern; overlapping repetitions add (Processing)"))
        }
        val doc = SchemaJson.decode(PatternDocument.serializer(), root, PatternReport)
        val pattern = HapticPattern(
            doc.name,
            doc.amplitude.mapIndexed { i, key -> AmplitudeKey(time(key.time, "amplitude[$i].time"), key.amplitude) },
            doc.frequency.mapIndexed { i, key -> FrequencyKey(time(key.time, "frequency[$i].time"), key.hertz) },
            doc.transients.mapIndexed { i, tap -> Transient(time(tap.time, "transients[$i].time"), tap.intensity, tap.sharpness) },
        )
        return PatternImport(pattern, emptyList())
    }

    private fun time(t: Double, path: String): Double {
        if (t < 0.0) throw PatternException(path, "must be >= 0 seconds, was $t")
        return t
    }

    private fun document(pattern: HapticPattern) = PatternDocument(
        SCHEMA, VERSION, pattern.name,
        pattern.amplitude.map { AmplitudePoint(it.time, it.amplitude) },
        pattern.frequency.map { FrequencyPoint(it.time, it.hertz) },
        pattern.transients.map { TransientPoint(it.time, it.intensity, it.sharpness) },
    )
}

/** A pattern document, schema `hapticon.pattern` ([PatternJson]); members in schema order. */
@Serializable
internal class PatternDocument(
    val schema: String,
    val version: Int,
    val name: String,
    val amplitude: List<AmplitudePoint>,
    val frequency: List<FrequencyPoint>,
    val transients: List<TransientPoint> = emptyList(),
)

/** One amplitude key of a [PatternDocument]. */
@Serializable
internal class AmplitudePoint(
    @Serializable(with = ShortDouble::class) val time: Double,
    @Serializable(with = ShortDouble::class) val amplitude: Double,
)

/** One frequency key of a [PatternDocument]. */
@Serializable
internal class FrequencyPoint(
    @Serializable(with = ShortDouble::class) val time: Double,
    @Serializable(with = ShortDouble::class) val hertz: Double,
)

/** One transient of a [PatternDocument]. */
@Serializable
internal class TransientPoint(
    @Serializable(with = ShortDouble::class) val time: Double,
    @Serializable(with = ShortDouble::class) val intensity: Double,
    @Serializable(with = ShortDouble::class) val sharpness: Double,
)

/** The pattern format's wording of schema problems, as the hand-written field readers worded them: a [PatternException] naming the member's path. */
internal object PatternReport : SchemaReport {
    override fun notAnObject(path: String, value: JsonElement): Nothing =
        throw PatternException(path.ifEmpty { "pattern" }, "expected an object, got ${snippet(value)}")

    override fun wrongType(path: String, member: String, expected: JsonKind, value: JsonElement?): Nothing {
        val at = if (path.isEmpty()) member else "$path.$member"
        if (value == null) throw PatternException(at, "missing")
        val number = (value as? JsonPrimitive)?.takeUnless { it.isString }?.content?.toDoubleOrNull()
        throw PatternException(
            at,
            when {
                expected == JsonKind.NUMBER && number != null && !number.isFinite() -> "must be finite"
                member == "schema" -> "expected \"${PatternJson.SCHEMA}\" or \"${IconJson.SCHEMA}\", got ${snippet(value)}"
                member == "version" -> "unsupported pattern schema version ${snippet(value)} (this build reads version ${PatternJson.VERSION})"
                else -> "expected ${article(expected)}, got ${snippet(value)}"
            },
        )
    }

    override fun wrongElement(path: String, member: String, index: Int, expected: JsonKind, value: JsonElement): Nothing {
        val at = if (path.isEmpty()) member else "$path.$member"
        throw PatternException("$at[$index]", "expected ${article(expected)}, got ${snippet(value)}")
    }

    // Schema and version come first: a newer document may have changed any other member.
    override fun checked(path: String, member: String, value: JsonElement) {
        if (path.isNotEmpty()) return
        val found = (value as? JsonPrimitive)?.content ?: return
        when (member) {
            "schema" -> if (found != PatternJson.SCHEMA) {
                throw PatternException("schema", "expected \"${PatternJson.SCHEMA}\" or \"${IconJson.SCHEMA}\", got \"$found\"")
            }
            "version" -> if (found != "${PatternJson.VERSION}") {
                throw PatternException("version", "unsupported pattern schema version $found (this build reads version ${PatternJson.VERSION})")
            }
        }
    }

    private fun article(kind: JsonKind): String = when (kind) {
        JsonKind.OBJECT -> "an object"
        JsonKind.ARRAY -> "an array"
        JsonKind.INT, JsonKind.LONG -> "an integer"
        JsonKind.STRING -> "a string"
        else -> "a ${kind.name.lowercase()}"
    }
}

/**
 * A pattern read from a file, with [notes] on anything the reader had to drop, assume or change
 * (for example "AudioCustom event at 0.5 s dropped: Hapticon plays haptics only").
 */
public data class PatternImport(val pattern: HapticPattern, val notes: List<String>)

/** A pattern written in another format: the file's [text] and [notes] on anything the format could not keep. */
public data class PatternExport(val text: String, val notes: List<String>)
