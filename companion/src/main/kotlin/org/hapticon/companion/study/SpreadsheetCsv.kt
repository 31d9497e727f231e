package org.hapticon.companion.study

import org.hapticon.study.export.Csv
import org.hapticon.study.export.CsvInjection

/**
 * The CSV the companion writes (collector downloads, analysis tables): RFC 4180 fields ([Csv.quote]) with formula
 * neutralising, because every cell may hold uploaded text and the file may be opened in a spreadsheet. Reading is the
 * study module's one reader, [Csv].
 */
object SpreadsheetCsv {
    /** [value] as one CSV field: quoted (quotes doubled) when it holds a comma, quote or line break. */
    fun field(value: String): String = Csv.quote(value)

    /** [values] as one CSV line ending in `\n`, each cell [neutralised][neutralise] first. */
    fun line(values: List<String>): String = values.joinToString(",", postfix = "\n") { field(neutralise(it)) }

    /**
     * [value], or `'` + [value] when a spreadsheet could run it as a formula: OWASP "CSV Injection" — a cell
     * starting with `=`, `+`, `-`, `@`, tab or carriage return is prefixed with a single quote, which
     * spreadsheets take as "this is text". Plain numbers such as `-1` or `+2.5e3` are left alone (no
     * spreadsheet evaluates them as a formula, and `hapticon analyze` must read negative responses back).
     * The stored value is never changed; only what is written out.
     */
    fun neutralise(value: String): String = CsvInjection.neutralise(value)

    /** [value], or `'` + [value] when it starts with `=`, `+`, `-`, `@`, tab or CR, numbers included (OWASP, strictly). */
    fun neutraliseText(value: String): String = if (value.isNotEmpty() && value[0] in FORMULA_STARTS) "'$value" else value

    private const val FORMULA_STARTS = "=+-@\t\r"
}
