package org.hapticon.core.pattern

import org.hapticon.core.io.SchemaJson

/** The pattern file formats, chosen by file extension. */
public enum class PatternFormat(public val extension: String) {
    /** Hapticon JSON: a pattern ([PatternJson]) or, when reading, an icon. */
    JSON("json"),

    /** Apple Core Haptics ([Ahap]). */
    AHAP("ahap"),

    /** Meta Haptics Studio / Lofelt ([MetaHaptic]). */
    HAPTIC("haptic"),
    ;

    public companion object {
        /** The format of a file called [fileName], or null for an extension no format has. */
        public fun ofFileName(fileName: String): PatternFormat? {
            val extension = fileName.substringAfterLast('.', "").lowercase()
            return entries.firstOrNull { it.extension == extension }
        }
    }
}

/** Reads and writes patterns in any [PatternFormat]. */
public object PatternFiles {
    /**
     * The pattern in [bytes] of [format], named [name] when the format carries no name. Throws [PatternException]
     * naming the member, or [org.hapticon.core.io.JsonException] for malformed JSON.
     */
    public fun read(bytes: ByteArray, format: PatternFormat, name: String, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): PatternImport =
        when (format) {
            PatternFormat.JSON -> PatternJson.read(SchemaJson.parseUtf8(bytes))
            PatternFormat.AHAP -> Ahap.read(bytes, name, mapping)
            PatternFormat.HAPTIC -> MetaHaptic.read(bytes, name, mapping)
        }

    /** [pattern] as the text of a [format] file, with notes on anything the format could not keep. */
    public fun write(pattern: HapticPattern, format: PatternFormat, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): PatternExport =
        when (format) {
            PatternFormat.JSON -> PatternExport(PatternJson.encode(pattern, "  ") + "\n", emptyList())
            PatternFormat.AHAP -> Ahap.write(pattern, mapping)
            PatternFormat.HAPTIC -> MetaHaptic.write(pattern, mapping)
        }
}
