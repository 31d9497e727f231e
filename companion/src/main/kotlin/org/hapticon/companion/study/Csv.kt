package org.hapticon.companion.study

import org.hapticon.study.export.CsvInjection
import java.io.IOException
import java.io.Reader
import org.hapticon.study.export.Csv as StudyCsv

/** A malformed CSV text (the study module's one CSV reader reports it). */
typealias CsvFormatException = org.hapticon.study.export.CsvFormatException

/** One CSV record and the 1-based line it starts on. */
typealias CsvRecord = org.hapticon.study.export.CsvRecord

/**
 * RFC 4180 CSV for the companion: reading is the study module's one reader ([StudyCsv]); writing adds formula
 * neutralising for cells that may hold uploaded text.
 */
object Csv {
    /** The records of [text] ([StudyCsv.parse]). */
    fun parse(text: String, source: String): List<CsvRecord> = StudyCsv.parse(text, source)

    /** Each record of [reader] in turn, streaming ([StudyCsv.forEachRecord]). */
    fun forEachRecord(reader: Reader, source: String, action: (CsvRecord) -> Unit) = StudyCsv.forEachRecord(reader, source, action)

    /** [value] as one CSV field: quoted (quotes doubled) when it holds a comma, quote or line break. */
    fun field(value: String): String = StudyCsv.quote(value)

    /**
     * [values] as one CSV line ending in `\n`, each cell [neutralised][neutralise] first: every CSV the companion
     * writes (collector downloads, analysis tables) may hold uploaded text and may be opened in a spreadsheet.
     */
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
