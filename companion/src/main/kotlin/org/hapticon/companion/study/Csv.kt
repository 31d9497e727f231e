package org.hapticon.companion.study

import org.hapticon.study.export.CsvInjection
import java.io.IOException
import java.io.Reader
import java.io.StringReader

/** A malformed CSV text: [source] (a file name or "upload"), 1-based [line], and what was wrong. */
class CsvFormatException(val source: String, val line: Int, val problem: String) : Exception("$source:$line: $problem")

/** One CSV record and the 1-based [line] it starts on (a quoted field may span several lines). */
class CsvRecord(val line: Int, val fields: List<String>)

/** RFC 4180 CSV: comma-separated, fields optionally in double quotes with `""` for a quote; CRLF or LF. */
object Csv {
    /**
     * The records of [text], blank lines skipped; [CsvFormatException] naming [source] and the line for an
     * unterminated quote or text after a closing quote. A leading UTF-8 BOM (spreadsheet exports) is ignored.
     */
    fun parse(text: String, source: String): List<CsvRecord> {
        val records = ArrayList<CsvRecord>()
        forEachRecord(StringReader(text), source) { records += it }
        return records
    }

    /**
     * Each record of [reader] in turn, as [parse] reads them, without holding the text or the records:
     * `hapticon analyze` reads a million-row file in a few MB this way. [IOException]s of [reader] pass through.
     */
    fun forEachRecord(reader: Reader, source: String, action: (CsvRecord) -> Unit) {
        val input = CsvRecordReader(reader, source)
        while (true) action(input.next() ?: return)
    }

    /** [value] as one CSV field: quoted (quotes doubled) when it holds a comma, quote or line break. */
    fun field(value: String): String =
        if (value.any { it == ',' || it == '"' || it == '\n' || it == '\r' }) "\"" + value.replace("\"", "\"\"") + "\"" else value

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
}

/** Reads one [CsvRecord] at a time from [reader] through its own buffer (no per-character virtual calls). */
private class CsvRecordReader(private val reader: Reader, private val source: String) {
    private val buffer = CharArray(1 shl 16)
    private var position = 0
    private var limit = 0
    private var line = 1
    private val field = StringBuilder()

    init {
        if (peek() == '\uFEFF'.code) position++
    }

    /** The next character without consuming it, or -1 at the end. */
    private fun peek(): Int {
        if (position == limit) {
            limit = reader.read(buffer)
            position = 0
            if (limit <= 0) {
                limit = 0
                return -1
            }
        }
        return buffer[position].code
    }

    /** The next non-blank record, or null at the end. */
    fun next(): CsvRecord? {
        while (peek() >= 0) {
            val start = line
            val fields = ArrayList<String>()
            var endOfRecord = false
            while (!endOfRecord) {
                if (peek() == '"'.code) {
                    position++
                    while (true) {
                        val c = peek()
                        if (c < 0) throw CsvFormatException(source, start, "unterminated quoted field")
                        position++
                        if (c == '"'.code) {
                            if (peek() == '"'.code) { field.append('"'); position++ } else break
                        } else {
                            if (c == '\n'.code) line++
                            field.append(c.toChar())
                        }
                    }
                    val after = peek()
                    if (after >= 0 && after != ','.code && after != '\n'.code && after != '\r'.code) {
                        throw CsvFormatException(source, line, "unexpected character '${after.toChar()}' after a closing quote")
                    }
                } else {
                    while (true) {
                        val c = peek()
                        if (c < 0 || c == ','.code || c == '\n'.code || c == '\r'.code) break
                        if (c == '"'.code) throw CsvFormatException(source, line, "quote inside an unquoted field")
                        field.append(c.toChar())
                        position++
                    }
                }
                fields += field.toString()
                field.setLength(0)
                val c = peek()
                when {
                    c < 0 -> endOfRecord = true
                    c == ','.code -> position++
                    else -> {
                        if (c == '\r'.code) position++
                        if (peek() == '\n'.code) position++
                        line++
                        endOfRecord = true
                    }
                }
            }
            if (!(fields.size == 1 && fields[0].isEmpty())) return CsvRecord(start, fields)
        }
        return null
    }
}
