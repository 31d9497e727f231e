package org.hapticon.study.log

/** What [HashChain.verify] found. */
public sealed interface ChainVerification {
    /** Every entry hashes correctly, links to the one before and has the next sequence number. */
    public data object Intact : ChainVerification

    /** The first bad entry is at list [index]: [problem] says what kind, [detail] says it in words. */
    public data class Broken(val index: Int, val problem: ChainProblem, val detail: String) : ChainVerification
}

/** Why a chain is broken. */
public enum class ChainProblem {
    /** The entry's content does not match its hash: a field was edited. */
    EDITED,

    /** Sequence numbers skip: one or more rows before this one were deleted. */
    DELETED,

    /** Sequence numbers are out of order: rows were moved or swapped. */
    REORDERED,

    /** The entry hashes correctly and is in sequence but does not link to the row before: a row was replaced by a forged one. */
    RELINKED,
}

/** Verification of a session's hash chain. */
public object HashChain {
    /**
     * Checks [entries], a whole session log from sequence 0, and returns [ChainVerification.Intact] or the first bad
     * index and why. A deleted last row cannot be seen from the rows alone; compare the last hash with one kept
     * elsewhere (the export carries it), or look for [StudyEvent.SessionEnded]. Does not throw.
     */
    public fun verify(entries: List<LogEntry>): ChainVerification {
        var previousHash = LogEntry.GENESIS_HASH
        entries.forEachIndexed { index, entry ->
            val expected = LogEntry.hashOf(entry.sequence, entry.timestampMillis, entry.participantId, entry.type, entry.payload, entry.previousHash)
            if (expected != entry.hash) {
                return ChainVerification.Broken(index, ChainProblem.EDITED, "entry ${entry.sequence} does not match its hash")
            }
            val wanted = index.toLong()
            if (entry.sequence != wanted) {
                // A row that turns up later was moved; one that never does was deleted.
                val reordered = entry.sequence < wanted || entries.subList(index + 1, entries.size).any { it.sequence == wanted }
                return if (reordered) {
                    ChainVerification.Broken(index, ChainProblem.REORDERED, "entry ${entry.sequence} is where entry $wanted belongs")
                } else {
                    ChainVerification.Broken(index, ChainProblem.DELETED, "entries $wanted..${entry.sequence - 1} are missing before entry ${entry.sequence}")
                }
            }
            if (entry.previousHash != previousHash) {
                return ChainVerification.Broken(index, ChainProblem.RELINKED, "entry ${entry.sequence} does not link to the entry before it")
            }
            previousHash = entry.hash
        }
        return ChainVerification.Intact
    }
}

/** [HashChain.verify] of this list. */
public fun List<LogEntry>.verifyChain(): ChainVerification = HashChain.verify(this)
