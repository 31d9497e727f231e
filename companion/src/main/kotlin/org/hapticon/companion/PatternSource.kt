package org.hapticon.companion

import org.hapticon.core.HapticIcon
import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.JsonObject
import org.hapticon.core.io.JsonString
import org.hapticon.core.pattern.FrequencyMapping
import org.hapticon.core.pattern.PatternException
import org.hapticon.core.pattern.PatternFiles
import org.hapticon.core.pattern.PatternFormat
import org.hapticon.core.pattern.PatternImport
import org.hapticon.core.pattern.PatternJson
import org.hapticon.core.pattern.toPattern
import java.io.File
import java.io.IOException

/**
 * Resolves a PATTERN argument: a preset name, or a file whose extension names its format — `.json` (a Hapticon
 * icon or pattern), `.ahap` (Apple Core Haptics) or `.haptic` (Meta Haptics Studio). Every problem is one
 * [UsageException] line naming the file and, for a bad member, its path in the file.
 */
object PatternSource {
    /** Whether [spec] is a pattern rather than an icon: an `.ahap`/`.haptic` file or a `hapticon.pattern` JSON file. */
    fun isPattern(spec: String): Boolean {
        if (HapticIcon.preset(spec) != null) return false
        val format = PatternFormat.ofFileName(spec) ?: return false
        if (format != PatternFormat.JSON) return true
        val file = File(spec)
        if (!file.isFile || file.length() > Json.DEFAULT_MAX_LENGTH) return false
        val root = try {
            Json.decodeUtf8(file.readBytes())
        } catch (e: JsonException) {
            return false // IconSource reports the JSON error
        }
        return root is JsonObject && root["schema"] == JsonString(PatternJson.SCHEMA)
    }

    /** The pattern [spec] names, with the reader's notes; [mapping] turns sharpness/normalised frequency into Hz. */
    fun load(spec: String, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): PatternImport {
        HapticIcon.preset(spec)?.let { return PatternImport(it.toPattern(), emptyList()) }
        val file = File(spec)
        val format = PatternFormat.ofFileName(spec)
            ?: throw UsageException("cannot tell the format of $spec: expected a preset or a .json, .ahap or .haptic file")
        if (!file.isFile) throw UsageException("no such pattern file: $spec")
        if (file.length() > Json.DEFAULT_MAX_LENGTH) throw UsageException("pattern file $spec is larger than ${Json.DEFAULT_MAX_LENGTH} bytes")
        val bytes = try {
            file.readBytes()
        } catch (e: IOException) {
            throw UsageException("cannot read pattern file $spec: ${e.message}")
        }
        return try {
            PatternFiles.read(bytes, format, file.nameWithoutExtension.take(HapticIcon.MAX_NAME_LENGTH).ifBlank { "pattern" }, mapping)
        } catch (e: JsonException) {
            throw UsageException("$spec is not valid JSON: ${e.message}")
        } catch (e: PatternException) {
            throw UsageException("$spec: ${e.message}")
        }
    }
}
