package org.hapticon.companion.study

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
        var i = if (text.startsWith("\uFEFF")) 1 else 0
        var line = 1
        while (i < text.length) {
            val start = line
            val fields = ArrayList<String>()
            val field = StringBuilder()
            var endOfRecord = false
            while (!endOfRecord) {
                if (i < text.length && text[i] == '"') {
                    i++
                    while (true) {
                        if (i >= text.length) throw CsvFormatException(source, start, "unterminated quoted field")
                        val c = text[i++]
                        if (c == '"') {
                            if (i < text.length && text[i] == '"') { field.append('"'); i++ } else break
                        } else {
                            if (c == '\n') line++
                            field.append(c)
                        }
                    }
                    if (i < text.length && text[i] != ',' && text[i] != '\n' && text[i] != '\r') {
                        throw CsvFormatException(source, line, "unexpected character '${text[i]}' after a closing quote")
                    }
                } else {
                    while (i < text.length && text[i] != ',' && text[i] != '\n' && text[i] != '\r') {
                        if (text[i] == '"') throw CsvFormatException(source, line, "quote inside an unquoted field")
                        field.append(text[i++])
                    }
                }
                fields += field.toString()
                field.setLength(0)
                when {
                    i >= text.length -> endOfRecord = true
                    text[i] == ',' -> i++
                    else -> {
                        if (text[i] == '\r') i++
                        if (i < text.length && text[i] == '\n') i++
                        line++
                        endOfRecord = true
                    }
                }
            }
            if (!(fields.size == 1 && fields[0].isEmpty())) records += CsvRecord(start, fields)
        }
        return records
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
    fun neutralise(value: String): String =
        if (value.isNotEmpty() && value[0] in FORMULA_STARTS && !PLAIN_NUMBER.matches(value)) "'$value" else value

    private const val FORMULA_STARTS = "=+-@\t\r"
    private val PLAIN_NUMBER = Regex("[+-]?(?:[0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
}
