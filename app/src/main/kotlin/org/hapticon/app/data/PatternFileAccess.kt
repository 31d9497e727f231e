package org.hapticon.app.data

import android.content.Context
import android.content.Intent
import android.net.Uri
import android.provider.OpenableColumns
import java.io.File
import java.io.IOException
import org.hapticon.app.study.StudyExporter
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternFormat
import org.hapticon.core.pattern.PatternImporter

/** Pattern files through Android: reading what the picker or share sheet hands over, and sharing an export. */
object PatternFileAccess {
    /**
     * The bytes and display name of [uri], reading at most [limit] bytes (a larger file is not read to its end;
     * [what] names the kind of file in that error). Throws [IOException] with a one-line message when it cannot be
     * read or is too large. Settings reads client certificates through it too.
     */
    fun read(context: Context, uri: Uri, limit: Int = PatternImporter.MAX_FILE_BYTES, what: String = "a pattern file"): Pair<ByteArray, String> {
        val name = displayName(context, uri)
        val input = try {
            context.contentResolver.openInputStream(uri)
        } catch (e: SecurityException) {
            throw IOException("$name: Hapticon may not read this file (${e.message})")
        } ?: throw IOException("$name: the file could not be opened")
        val bytes = input.use { stream ->
            val buffer = ByteArray(limit + 1)
            var filled = 0
            while (filled < buffer.size) {
                val n = stream.read(buffer, filled, buffer.size - filled)
                if (n < 0) break
                filled += n
            }
            if (filled > limit) throw IOException("$name: larger than $what may be ($limit bytes)")
            buffer.copyOf(filled)
        }
        return bytes to name
    }

    /** The name the providing app gives [uri], else its last path segment. */
    fun displayName(context: Context, uri: Uri): String {
        val queried = runCatching {
            context.contentResolver.query(uri, arrayOf(OpenableColumns.DISPLAY_NAME), null, null, null)?.use { cursor ->
                if (cursor.moveToFirst()) cursor.getString(0) else null
            }
        }.getOrNull()
        return (queried ?: uri.lastPathSegment ?: "pattern").replace(Regex("[\\r\\n]"), " ")
    }

    /**
     * Writes [text] as `<name>.<extension>` into the exports directory the FileProvider serves and returns the share
     * sheet's intent for it.
     */
    fun share(context: Context, pattern: HapticPattern, format: PatternFormat, text: String): Intent {
        val directory = File(context.cacheDir, "exports").apply { mkdirs() }
        val safe = pattern.name.replace(Regex("[^A-Za-z0-9._ -]"), "_").trim().ifEmpty { "pattern" }
        val file = File(directory, "$safe.${format.extension}").apply { writeText(text) }
        val mime = if (format == PatternFormat.JSON) "application/json" else "application/octet-stream"
        return Intent.createChooser(StudyExporter.shareIntent(context, file, mime), "Export ${pattern.name}")
    }
}
