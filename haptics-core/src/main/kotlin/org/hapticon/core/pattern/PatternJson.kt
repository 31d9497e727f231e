package org.hapticon.core.pattern

import org.hapticon.core.IconValidationException
import org.hapticon.core.io.IconJson
import org.hapticon.core.io.JsonArray
import org.hapticon.core.io.JsonNumber
import org.hapticon.core.io.JsonObject
import org.hapticon.core.io.JsonString
import org.hapticon.core.io.JsonValue

/**
 * Patterns as Hapticon JSON: `{"schema": "hapticon.pattern", "version": 1, "name": "boing",
 * "amplitude": [{"time": 0, "amplitude": 0.64}, …], "frequency": [{"time": 0, "hertz": 180}],
 * "transients": [{"time": 0, "intensity": 0.8, "sharpness": 0.4}]}` — the pattern's own fields, nothing
 * lost. `transients` may be omitted. [read] also takes an icon (`"schema": "hapticon.icon"`, [IconJson]) and
 * returns it as a pattern, so every command that takes a pattern takes an icon file too.
 */
public object PatternJson {
    /** The value of the `schema` member. */
    public const val SCHEMA: String = "hapticon.pattern"

    /** The schema version this build writes, and the newest it reads. */
    public const val VERSION: Int = 1

    /** [pattern] as a JSON object. Does not throw. */
    public fun toJsonValue(pattern: HapticPattern): JsonObject = JsonObject(
        linkedMapOf(
            "schema" to JsonString(SCHEMA),
            "version" to JsonNumber(VERSION),
            "name" to JsonString(pattern.name),
            "amplitude" to JsonArray(pattern.amplitude.map { obj("time" to it.time, "amplitude" to it.amplitude) }),
            "frequency" to JsonArray(pattern.frequency.map { obj("time" to it.time, "hertz" to it.hertz) }),
            "transients" to JsonArray(
                pattern.transients.map { obj("time" to it.time, "intensity" to it.intensity, "sharpness" to it.sharpness) },
            ),
        ),
    )

    /**
     * The pattern [value] describes: a pattern document, or an icon document converted by [toPattern] (with a
     * note saying so). Throws [PatternException] naming the member for anything malformed or out of range.
     */
    public fun read(value: JsonValue): PatternImport {
        val root = value.asObject("pattern")
        val schema = root["schema"].asString("schema")
        if (schema == IconJson.SCHEMA) {
            val icon = try {
                IconJson.fromJsonValue(root)
            } catch (e: IconValidationException) {
                fail(e.field, e.message!!.removePrefix("${e.field}: "))
            }
            return PatternImport(icon.toPattern(), listOf("icon '${icon.name}' became a pattern; overlapping repetitions add (Processing)"))
        }
        if (schema != SCHEMA) fail("schema", "expected \"$SCHEMA\" or \"${IconJson.SCHEMA}\", got \"$schema\"")
        val version = root["version"].asNumber("version")
        if (version != VERSION.toDouble()) fail("version", "unsupported pattern schema version $version (this build reads version $VERSION)")
        val amplitude = root["amplitude"].asArray("amplitude").objects("amplitude").map { (path, key) ->
            AmplitudeKey(key["time"].asTime("$path.time"), key["amplitude"].asNumber("$path.amplitude"))
        }
        val frequency = root["frequency"].asArray("frequency").objects("frequency").map { (path, key) ->
            FrequencyKey(key["time"].asTime("$path.time"), key["hertz"].asNumber("$path.hertz"))
        }
        val transients = (root["transients"] ?: JsonArray(emptyList())).asArray("transients").objects("transients").map { (path, tap) ->
            Transient(tap["time"].asTime("$path.time"), tap["intensity"].asNumber("$path.intensity"), tap["sharpness"].asNumber("$path.sharpness"))
        }
        return PatternImport(HapticPattern(root["name"].asString("name"), amplitude, frequency, transients), emptyList())
    }

    private fun obj(vararg members: Pair<String, Double>): JsonObject =
        JsonObject(linkedMapOf(*members.map { (k, v) -> k to (JsonNumber(v) as JsonValue) }.toTypedArray()))
}

/**
 * A pattern read from a file, with [notes] on anything the reader had to drop, assume or change
 * (for example "AudioCustom event at 0.5 s dropped: Hapticon plays haptics only").
 */
public data class PatternImport(val pattern: HapticPattern, val notes: List<String>)

/** A pattern written in another format: the file's [text] and [notes] on anything the format could not keep. */
public data class PatternExport(val text: String, val notes: List<String>)
