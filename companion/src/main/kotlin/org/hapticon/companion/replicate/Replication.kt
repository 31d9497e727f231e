package org.hapticon.companion.replicate

import org.hapticon.companion.cli.UsageException
import java.io.PrintStream

/**
 * One published result reproduced by `hapticon replicate ID`. [id] is the paper's seed-file number (000 … 004, the
 * numbering of docs/replication.md); [names] are short names the command accepts as well (`replicate eit-skin`).
 */
interface Replication {
    val id: String
    val names: List<String> get() = emptyList()
    val title: String

    /** Options after the id (`replicate nao --data DIR`), for the usage line; empty when it takes none. */
    val options: String get() = ""

    /** Prints the replication. */
    fun run(out: PrintStream)

    /**
     * Checks [args], the words after the id, before anything is printed: a [UsageException] names the problem. A
     * replication without [options] takes none.
     */
    fun check(args: List<String>) {
        if (args.isNotEmpty()) throw UsageException("replicate $id takes no options, got ${args.joinToString(" ")}")
    }

    /** Prints the replication with [args], which [check] accepted. */
    fun run(out: PrintStream, args: List<String>) = run(out)
}

/**
 * A paper's full text as the replications cite it: [seedFile] is its file in the papers' index
 * (`002_12aacdd60a14fec1.txt`), cited in tables as `002:LINE` ([at]).
 */
class PaperText(val seedFile: String) {
    /** The short key, the seed file's number: `002`. */
    val key: String = seedFile.substringBefore('_')

    /** A citation of [lines] (`"62"`, `"259-262"`, `"138, 169-170"`): `002:62`. */
    fun at(lines: String): String = "$key:$lines"

    /** The line that names the file once above a table whose citations use [key]. */
    val legend: String get() = "paper text: $seedFile, cited as $key:LINE"
}

/**
 * One published rule beside ours: the [rule], the paper's value ([paper]) and where its text states it ([cited],
 * e.g. `002:62`, or "—" where the paper is silent), [ours], and [verdict]: `same`, `different: why`, `paper silent:
 * our choice and why`, or `not built: why`.
 */
class RuleRow(val rule: String, val paper: String, val cited: String, val ours: String, val verdict: String)

/** Prints [rows] as a `rule | paper | cited | ours | same/different and why` table. */
fun PrintStream.printRules(rows: List<RuleRow>) =
    printTable(listOf("rule", "paper", "cited", "ours", "same/different and why"), rows.map { listOf(it.rule, it.paper, it.cited, it.ours, it.verdict) })

/**
 * Prints figures computed on simulated people in a table of their own, under a heading that says so: they show how
 * our pipeline behaves, and are never comparable with a paper's figure (the paper's people are not ours).
 */
fun PrintStream.printSimulated(what: String, header: List<String>, rows: List<List<String>>) {
    println("SIMULATED, not comparable with the paper's figures: $what")
    printTable(header, rows)
}

/**
 * Prints [header] and [rows] with every column padded to its widest cell, cells separated by ` | `; a column after
 * the first whose cells are all numbers (with an optional unit or %) is right-aligned. Rows shorter than the header
 * are padded with blanks.
 */
fun PrintStream.printTable(header: List<String>, rows: List<List<String>>) {
    val all = listOf(header) + rows.map { r -> List(header.size) { r.getOrElse(it) { "" } } }
    val widths = header.indices.map { c -> all.maxOf { it[c].length } }
    // The first column names the rows and stays left-aligned.
    val numeric = header.indices.map { c -> c > 0 && rows.isNotEmpty() && rows.all { r -> NUMBER.matches(r.getOrElse(c) { "" }) } }
    for (r in all) {
        println(r.indices.joinToString(" | ") { c -> if (numeric[c]) r[c].padStart(widths[c]) else r[c].padEnd(widths[c]) }.trimEnd())
    }
}

private val NUMBER = Regex("""[-+−]?\d[\d.,]*( ?(%|°|V|mV|Hz|s|ms|kΩ|Ω|kOhm))?|—|""")
