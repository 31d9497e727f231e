package org.hapticon.companion.replicate

/**
 * One published result reproduced by `hapticon replicate ID`. [id] is the paper's seed-file number (000 … 004, the
 * numbering of docs/replication.md); [names] are short names the command accepts as well (`replicate eit-skin`).
 */
interface Replication {
    val id: String
    val names: List<String> get() = emptyList()
    val title: String
    fun run(out: java.io.PrintStream)
}
