package org.hapticon.companion.cli

import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive

import org.hapticon.core.HapticIcon
import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.SchemaJson
import org.hapticon.core.pattern.FrequencyMapping
import org.hapticon.core.pattern.PatternException
import org.hapticon.core.pattern.PatternFiles
import org.hapticon.core.pattern.PatternFormat
import org.hapticon.core.pattern.PatternImport
import org.hapticon.core.pattern.PatternJson
import org.hapticon.core.pattern.toPattern
import org.hapticon.core.io.WavEncoding
import org.hapticon.core.io.WavWriter
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.signal
import org.hapticon.core.render.stream
import java.util.Locale
import java.io.File
import java.io.IOException

/**
 * Resolves a PATTERN argument: a preset name, or a file whose extension names its format — `.json` (a Hapticon
 * icon or pattern), `.ahap` (Apple Core Haptics) or `.haptic` (Meta Haptics Studio). Every problem is one
 * [UsageException] line naming the file and, for a bad member, its path in the file.
 */
object PatternSource {
    /**
     * The pattern [spec] names when it is one rather than an icon (an `.ahap`/`.haptic` file, or a `.json` file
     * whose schema is `hapticon.pattern`), read once; null for a preset or an icon file, which [IconSource] reads.
     */
    fun loadIfPattern(spec: String, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): PatternImport? {
        if (HapticIcon.preset(spec) != null) return null
        val format = PatternFormat.ofFileName(spec) ?: return null
        if (format != PatternFormat.JSON) return load(spec, mapping)
        val file = File(spec)
        if (!file.isFile || file.length() > Json.DEFAULT_MAX_LENGTH) return null
        val bytes = readBytes(spec, file)
        val root = try {
            SchemaJson.parseUtf8(bytes)
        } catch (e: JsonException) {
            return null // IconSource reports the JSON error
        }
        if (root !is JsonObject || root["schema"] != JsonPrimitive(PatternJson.SCHEMA)) return null
        return parse(spec, file, PatternFormat.JSON, bytes, mapping)
    }

    /** The pattern [spec] names, with the reader's notes; [mapping] turns sharpness/normalised frequency into Hz. */
    fun load(spec: String, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): PatternImport {
        HapticIcon.preset(spec)?.let { return PatternImport(it.toPattern(), emptyList()) }
        val file = File(spec)
        val format = PatternFormat.ofFileName(spec)
            ?: throw UsageException("cannot tell the format of $spec: expected a preset or a .json, .ahap or .haptic file")
        if (!file.isFile) throw UsageException("no such pattern file: $spec")
        if (file.length() > Json.DEFAULT_MAX_LENGTH) throw UsageException("pattern file $spec is larger than ${Json.DEFAULT_MAX_LENGTH} bytes")
        return parse(spec, file, format, readBytes(spec, file), mapping)
    }

    private fun readBytes(spec: String, file: File): ByteArray = try {
        file.readBytes()
    } catch (e: IOException) {
        throw UsageException("cannot read pattern file $spec: ${e.message}")
    }

    private fun parse(spec: String, file: File, format: PatternFormat, bytes: ByteArray, mapping: FrequencyMapping): PatternImport = try {
        PatternFiles.read(bytes, format, file.nameWithoutExtension.take(HapticIcon.MAX_NAME_LENGTH).ifBlank { "pattern" }, mapping)
    } catch (e: JsonException) {
        throw UsageException("$spec is not valid JSON: ${e.message}")
    } catch (e: PatternException) {
        throw UsageException("$spec: ${e.message}")
    }
}

/** Throws [UsageException] unless [pattern] can be sampled at [rate]: a supported rate, every carrier below Nyquist. */
fun checkRenderable(pattern: HapticPattern, rate: Int, mapping: FrequencyMapping = FrequencyMapping.DEFAULT) {
    if (rate !in 8_000..192_000) throw UsageException("--rate must be in 8000..192000 Hz, was $rate")
    val highest = (pattern.frequency.map { it.hertz } + mapping.maxHz).max()
    if (highest >= rate / 2.0) throw UsageException(String.format(Locale.ROOT, "cannot render %s at %d Hz: it reaches %.1f Hz, at or above Nyquist", pattern.name, rate, highest))
}

/** Renders [pattern] into the WAV [file] and returns the summary line. */
fun writeWav(pattern: HapticPattern, file: File, rate: Int, encoding: WavEncoding, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): String {
    checkRenderable(pattern, rate, mapping)
    val stream = pattern.signal(mapping).stream(rate)
    OutputFiles.write(file) { WavWriter.write(stream, it, encoding) }
    return String.format(Locale.ROOT, "wrote %s: %s, %d samples, %.3f s at %d Hz, %s", file, pattern.name, stream.totalSamples,
        stream.totalSamples.toDouble() / rate, rate, encoding.cliName())
}
