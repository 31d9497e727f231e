package org.hapticon.companion.cli

import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException
import org.hapticon.core.io.IconJson
import org.hapticon.core.io.Json
import org.hapticon.core.io.JsonException
import org.hapticon.core.io.SchemaJson
import java.io.File
import java.io.IOException

/** Resolves the ICON argument: a preset name first, otherwise the path of an icon JSON file. */
object IconSource {
    /**
     * The icon [spec] names. Throws [UsageException] naming the problem when it is neither a preset nor a
     * readable file, or the file is not valid JSON or not a valid icon (the message names the field).
     */
    fun load(spec: String): HapticIcon {
        HapticIcon.preset(spec)?.let { return it }
        val file = File(spec)
        if (!file.exists()) {
            val presets = HapticIcon.PRESETS.joinToString(", ") { it.name }
            throw UsageException("unknown icon '$spec': not a preset ($presets) and no such file")
        }
        if (!file.isFile) throw UsageException("icon file $spec is not a regular file")
        // Checked before reading so that a huge file is never loaded; the JSON reader has the same limit.
        if (file.length() > Json.DEFAULT_MAX_LENGTH) {
            throw UsageException("icon file $spec is larger than ${Json.DEFAULT_MAX_LENGTH} bytes")
        }
        val bytes = try {
            file.readBytes()
        } catch (e: IOException) {
            throw UsageException("cannot read icon file $spec: ${e.message}")
        }
        return try {
            IconJson.fromJsonElement(SchemaJson.parseUtf8(bytes))
        } catch (e: JsonException) {
            throw UsageException("icon file $spec is not valid JSON: ${e.message}")
        } catch (e: IconValidationException) {
            throw UsageException("icon file $spec is not a valid icon: ${e.message}")
        }
    }
}
