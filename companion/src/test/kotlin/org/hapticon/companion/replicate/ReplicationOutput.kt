package org.hapticon.companion.replicate

/** What a replication printed, read as the tables `printTable` writes: lines, and lines split into trimmed cells. */
class ReplicationOutput(val text: String) {
    val lines: List<String> = text.lines()

    /** The cells of [line]: split at ` | `, trimmed. */
    fun cells(line: String): List<String> = line.split(" | ").map { it.trim() }

    /** The cells of the first table row whose first cell is [first] at or after line [from]. */
    fun row(first: String, from: Int = 0): List<String> =
        lines.drop(from).firstOrNull { it.contains(" | ") && cells(it)[0] == first }?.let(::cells)
            ?: throw AssertionError("no table row '$first' in\n$text")

    /** The index of the first line starting with [prefix]. */
    fun indexOf(prefix: String): Int = lines.indexOfFirst { it.startsWith(prefix) }.also { if (it < 0) throw AssertionError("no line '$prefix' in\n$text") }
}
