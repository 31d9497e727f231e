package org.hapticon.app.data

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.map
import org.hapticon.app.data.database.PatternDao
import org.hapticon.app.data.database.asEntity
import org.hapticon.app.data.database.asExternalModel
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternFiles
import org.hapticon.core.pattern.PatternFormat
import org.hapticon.core.pattern.PatternImportException
import org.hapticon.core.pattern.PatternImporter
import org.hapticon.messaging.Clock

/** A pattern in the user's library, with where it came from (an imported file's name, or null when made here). */
data class StoredPattern(val pattern: HapticPattern, val source: String?)

/** What [RoomPatternRepository.import] did: the pattern it saved with the reader's notes, or why it saved nothing. */
sealed interface PatternImportOutcome {
    data class Imported(val pattern: HapticPattern, val notes: List<String>) : PatternImportOutcome

    /** [message] is one line naming the file and the problem; nothing was stored. */
    data class Failed(val message: String) : PatternImportOutcome
}

/** The user's haptic patterns in Room: imported AHAP, `.haptic` and pattern JSON files and edited copies. */
class RoomPatternRepository(private val dao: PatternDao, private val clock: Clock = Clock.SYSTEM) {
    /** Every stored pattern by name; a row that no longer reads (a stricter future rule) is skipped, not fatal. */
    fun patterns(): Flow<List<StoredPattern>> = dao.patterns().map { rows ->
        rows.mapNotNull { row -> runCatching { StoredPattern(row.asExternalModel(), row.source) }.getOrNull() }
    }

    /** Stores [pattern], replacing one of the same name. */
    suspend fun save(pattern: HapticPattern, source: String? = null) = dao.upsert(pattern.asEntity(source, clock.nowMillis()))

    suspend fun delete(name: String) = dao.delete(name)

    /**
     * Reads [bytes], a file called [fileName] from outside the app (share sheet, file picker), with
     * [PatternImporter]'s limits, and stores the pattern under a name no stored pattern has yet
     * ("boing", "boing 2", …): an import never overwrites.
     */
    suspend fun import(bytes: ByteArray, fileName: String, taken: Set<String>): PatternImportOutcome {
        val imported = try {
            PatternImporter.read(bytes, fileName)
        } catch (e: PatternImportException) {
            return PatternImportOutcome.Failed(e.message!!)
        }
        val pattern = imported.pattern.named(freeName(imported.pattern.name, taken))
        save(pattern, source = fileName)
        return PatternImportOutcome.Imported(pattern, imported.notes)
    }

    /** [pattern] as the text of a [format] file, with notes on what that format cannot keep. */
    fun export(pattern: HapticPattern, format: PatternFormat) = PatternFiles.write(pattern, format)

    private fun freeName(name: String, taken: Set<String>): String {
        if (name !in taken) return name
        return (2..Int.MAX_VALUE).asSequence().map { n -> "${name.take(org.hapticon.core.HapticIcon.MAX_NAME_LENGTH - 4)} $n" }.first { it !in taken }
    }
}
