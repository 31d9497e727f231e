package org.hapticon.study.export

import java.io.IOException
import java.io.Reader
import java.io.StringReader

/** What was wrong with a CSV text's quoting; [CsvFormatException.kind]. */
public enum class CsvProblem {
    /** A quoted field runs to the end of the text. */
    UNTERMINATED_QUOTE,

    /** Something other than a comma or line end follows a closing quote. */
    TEXT_AFTER_QUOTE,

    /** A quote inside a field that does not start with one (RFC 4180 §2.5 forbids it). */
    QUOTE_IN_FIELD,
}

/**
 * A malformed CSV text: [source] (a file name or "upload"), 1-based [line], and what was wrong ([problem]); [kind]
 * says which quoting rule was broken, or is null for a problem its reader found in the records' content.
 */
public class CsvFormatException(
    public val source: String,
    public val line: Int,
    public val problem: String,
    public val kind: CsvProblem? = null,
) : Exception("$source:$line: $problem")

/** One CSV record and the 1-based [line] it starts on (a quoted field may span several lines). */
public class CsvRecord(public val line: Int, public val fields: List<String>)

/**
 * The one CSV reader (RFC 4180): comma-separated, fields optionally in double quotes with `""` for a quote; CRLF or
 * LF; blank lines skipped; a leading UTF-8 byte order mark (spreadsheet exports) ignored. It is strict where RFC 4180
 * is: a quote may not appear inside an unquoted field (§2.5), and only a comma or line end may follow a closing quote.
 *
 * Hand-written rather than Apache Commons CSV: commons-csv enters quoted mode only at the start of a field and keeps
 * a later quote as text, with no option to refuse it (the strict rule above), and reports errors as IOExceptions in
 * its own words; streaming speed was measured against it in `hapticon bench --analysis` (docs/study-analysis.md).
 */
public object Csv {
    /** The records of [text], as [forEachRecord] reads them. */
    public fun parse(text: String, source: String): List<CsvRecord> {
        val records = ArrayList<CsvRecord>()
        forEachRecord(StringReader(text), source) { records += it }
        return records
    }

    /**
     * Each record of [reader] in turn, without holding the text or the records: `hapticon analyze` reads a
     * million-row file in a few MB this way. [CsvFormatException] naming [source] and the line for an unterminated
     * quote, text after a closing quote or a quote inside an unquoted field; [IOException]s of [reader] pass through.
     */
    public fun forEachRecord(reader: Reader, source: String, action: (CsvRecord) -> Unit) {
        val input = CsvRecordReader(reader, source)
        while (true) action(input.next() ?: return)
    }

    /** [field] as written in a record: quoted (quotes doubled) when it holds a comma, quote, CR or LF. */
    public fun quote(field: String): String =
        if (field.any { it == ',' || it == '"' || it == '\r' || it == '\n' }) "\"" + field.replace("\"", "\"\"") + "\"" else field
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

    private fun fail(line: Int, problem: String, kind: CsvProblem): Nothing = throw CsvFormatException(source, line, problem, kind)

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
                        if (c < 0) fail(start, "unterminated quoted field", CsvProblem.UNTERMINATED_QUOTE)
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
                        fail(line, "unexpected character '${after.toChar()}' after a closing quote", CsvProblem.TEXT_AFTER_QUOTE)
                    }
                } else {
                    while (true) {
                        val c = peek()
                        if (c < 0 || c == ','.code || c == '\n'.code || c == '\r'.code) break
                        if (c == '"'.code) fail(line, "quote inside an unquoted field", CsvProblem.QUOTE_IN_FIELD)
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
