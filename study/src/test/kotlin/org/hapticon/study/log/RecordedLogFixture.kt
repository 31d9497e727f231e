package org.hapticon.study.log

/**
 * The events of `recorded/study-log-v1.txt`: a session whose ids hold every character class the old hand-written
 * writer escaped specially (quote, backslash, control characters, U+2028/U+2029) or left alone (DEL, `/`, é, emoji).
 */
internal object RecordedLogFixture {
    const val PARTICIPANT = "P\u2028\"07\\E"
    const val RESOURCE = "/recorded/study-log-v1.txt"

    val EVENTS: List<Pair<StudyEvent, Long>> = listOf(
        StudyEvent.SessionStarted("stu\u2029dy/é", 3, 7, Long.MIN_VALUE) to 1_700_000_000_000,
        StudyEvent.TaskStarted("t\u2028ä\t\n") to 1_700_000_000_100,
        StudyEvent.StimulusShown("t\u2028ä\t\n", "s\u0001\u001f\u007f\b\u000C\r😀") to 1_700_000_000_200,
        StudyEvent.IconPressed("t\u2028ä\t\n", "s\u0001\u001f\u007f\b\u000C\r😀") to 1_700_000_000_300,
        StudyEvent.PlaybackStarted("t\u2028ä\t\n", "s\u0001\u001f\u007f\b\u000C\r😀") to 1_700_000_000_301,
        StudyEvent.PlaybackFinished("t\u2028ä\t\n", "s\u0001\u001f\u007f\b\u000C\r😀") to 1_700_000_000_900,
        StudyEvent.Answer("t\u2028ä\t\n", "s\u0001\u001f\u007f\b\u000C\r😀", 5) to 1_700_000_001_000,
        StudyEvent.ExplorationEnded("t\u2028ä\t\n") to 1_700_000_001_100,
        StudyEvent.TaskEnded("t\u2028ä\t\n") to 1_700_000_001_200,
        StudyEvent.SessionEnded to Long.MAX_VALUE,
    )

    /** The log as this build writes it. */
    fun write(): List<LogEntry> {
        val entries = ArrayList<LogEntry>()
        for ((index, pair) in EVENTS.withIndex()) {
            val previous = entries.lastOrNull()?.hash ?: LogEntry.GENESIS_HASH
            entries += LogEntry.create(index.toLong(), pair.second, PARTICIPANT, pair.first, previous)
        }
        return entries
    }
}
