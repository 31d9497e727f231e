package org.hapticon.core.pattern

/**
 * Reads pattern files that come from outside (the Android share sheet, a file picker, a chat attachment), where
 * nothing about the file can be trusted: not its size, its name or its numbers.
 *
 * - The size is checked before anything is parsed: at most [MAX_FILE_BYTES]. A pattern never needs more (a
 *   pattern JSON of [HapticPattern.MAX_KEYS] keys in every curve is about 0.6 MB), so a larger file (say 10⁶
 *   breakpoints) is refused at once.
 * - The format comes from the file name's extension; a name without a known one (content URIs often have none)
 *   is recognised by content: `"Pattern"` → AHAP, `"signals"` → Meta `.haptic`, else Hapticon JSON.
 * - Every problem (malformed JSON, NaN-like overflow `1e999`, a negative or decreasing time, a duration over the
 *   30 s safety cap ([HapticPattern.checkPlayable]: what the app imports is there to be played and sent), too
 *   many keys, an amplitude outside 0..1) becomes one [PatternImportException] whose
 *   message is one line naming the file and the member: `boing.ahap: Pattern[2].Event.Time: must be …`.
 */
public object PatternImporter {
    /** Largest pattern file read, in bytes (1 MiB). */
    public const val MAX_FILE_BYTES: Int = 1 shl 20

    /**
     * The pattern in [bytes], a file called [fileName]. Throws [PatternImportException] with a one-line message
     * for anything that is not a valid pattern within the limits.
     */
    public fun read(bytes: ByteArray, fileName: String, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): PatternImport {
        val shownName = oneLine(fileName.ifBlank { "pattern" })
        if (bytes.size > MAX_FILE_BYTES) {
            throw PatternImportException("$shownName: ${bytes.size} bytes is larger than a pattern file may be ($MAX_FILE_BYTES bytes)")
        }
        val format = formatOf(fileName, bytes)
        val name = patternName(fileName)
        return try {
            PatternFiles.read(bytes, format, name, mapping).also { it.pattern.checkPlayable() }
        } catch (e: IllegalArgumentException) {
            // PatternException and JsonException are both IllegalArgumentExceptions with a field or offset in the message.
            throw PatternImportException("$shownName: ${oneLine(e.message ?: e.javaClass.simpleName)}")
        } catch (e: StackOverflowError) {
            throw PatternImportException("$shownName: nested too deeply")
        }
    }

    /** The format of [fileName] by extension, else by a look at [bytes]. */
    public fun formatOf(fileName: String, bytes: ByteArray): PatternFormat {
        PatternFormat.ofFileName(fileName)?.let { return it }
        val head = String(bytes, 0, minOf(bytes.size, 4096), Charsets.UTF_8)
        return when {
            "\"Pattern\"" in head -> PatternFormat.AHAP
            "\"signals\"" in head -> PatternFormat.HAPTIC
            else -> PatternFormat.JSON
        }
    }

    /** A pattern name from a file name: the base name without extension, cut to a valid name length. */
    public fun patternName(fileName: String): String {
        val base = fileName.substringAfterLast('/').substringBeforeLast('.').trim()
        return oneLine(base).take(org.hapticon.core.HapticIcon.MAX_NAME_LENGTH).ifBlank { "pattern" }
    }

    private fun oneLine(text: String): String = text.replace(Regex("\\s+"), " ").let { if (it.length > 300) it.take(300) + "…" else it }
}

/** A pattern file that could not be read; [message] is one line naming the file and the problem. */
public class PatternImportException(message: String) : IllegalArgumentException(message)
