package org.hapticon.study.export

/** RFC 4180 quoting and parsing, shared by the study's CSV files. */
internal object Csv {
    /** [field] as written in a record: quoted when it holds a comma, quote, CR or LF. */
    fun quote(field: String): String =
        if (field.any { it == ',' || it == '"' || it == '\r' || it == '\n' }) "\"" + field.replace("\"", "\"\"") + "\"" else field

    /**
     * The records of [text] with the 1-based line each starts on. Accepts CRLF and LF line ends and a missing final
     * line end; skips a final empty line. Throws [IllegalArgumentException] for an unterminated quote or text after a
     * closing quote.
     */
    fun parse(text: String): List<Pair<Int, List<String>>> {
        val records = ArrayList<Pair<Int, List<String>>>()
        var fields = ArrayList<String>()
        val field = StringBuilder()
        var line = 1
        var recordLine = 1
        var i = 0
        var atRecordStart = true
        while (i < text.length) {
            val c = text[i]
            when {
                c == '"' && field.isEmpty() -> {
                    val quoteLine = line
                    i++
                    while (true) {
                        if (i >= text.length) throw IllegalArgumentException("line $quoteLine: unterminated quoted field")
                        val q = text[i]
                        if (q == '"') {
                            if (i + 1 < text.length && text[i + 1] == '"') { field.append('"'); i += 2; continue }
                            i++
                            break
                        }
                        if (q == '\n') line++
                        field.append(q)
                        i++
                    }
                    if (i < text.length && text[i] != ',' && text[i] != '\r' && text[i] != '\n') {
                        throw IllegalArgumentException("line $line: text after a closing quote")
                    }
                    atRecordStart = false
                    continue
                }
                c == ',' -> { fields += field.toString(); field.setLength(0); atRecordStart = false }
                c == '\r' && i + 1 < text.length && text[i + 1] == '\n' -> { i++; continue }
                c == '\n' -> {
                    fields += field.toString(); field.setLength(0)
                    records += recordLine to fields
                    fields = ArrayList(); line++; recordLine = line; atRecordStart = true
                }
                else -> { field.append(c); atRecordStart = false }
            }
            i++
        }
        if (!atRecordStart) {
            fields += field.toString()
            records += recordLine to fields
        }
        return records
    }
}
