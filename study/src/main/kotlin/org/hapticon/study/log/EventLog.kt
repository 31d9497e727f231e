package org.hapticon.study.log

/**
 * A session's log being written: [append] chains each new event to the last entry. Not thread-safe; a ViewModel
 * appends from one thread and persists [entries] (or each returned entry) as it goes.
 */
public class EventLog private constructor(
    /** The pseudonymous participant id every entry carries. */
    public val participantId: String,
    existing: List<LogEntry>,
) {
    private val list = ArrayList(existing)

    /** The entries so far, oldest first. A snapshot: later appends do not show through. */
    public val entries: List<LogEntry> get() = list.toList()

    /** The events so far, oldest first. */
    public val events: List<StudyEvent> get() = list.map { it.event }

    /** Records [event] at [timestampMillis] (epoch ms) and returns the new entry. Does not throw. */
    public fun append(event: StudyEvent, timestampMillis: Long): LogEntry {
        val previous = list.lastOrNull()
        val entry = LogEntry.create(list.size.toLong(), timestampMillis, participantId, event, previous?.hash ?: LogEntry.GENESIS_HASH)
        list += entry
        return entry
    }

    public companion object {
        /** An empty log for [participantId]. */
        public fun start(participantId: String): EventLog = EventLog(participantId, emptyList())

        /**
         * Continues [entries] (for example reloaded after the app was killed). Throws [IllegalArgumentException] when
         * the chain is broken, saying where and why, or when an entry belongs to another participant than [participantId].
         */
        public fun resume(participantId: String, entries: List<LogEntry>): EventLog {
            val verification = HashChain.verify(entries)
            require(verification is ChainVerification.Intact) {
                val broken = verification as ChainVerification.Broken
                "cannot resume a broken log: ${broken.problem.name.lowercase()} at index ${broken.index}: ${broken.detail}"
            }
            entries.firstOrNull { it.participantId != participantId }?.let {
                throw IllegalArgumentException("entry ${it.sequence} belongs to ${it.participantId}, not $participantId")
            }
            return EventLog(participantId, entries)
        }
    }
}
