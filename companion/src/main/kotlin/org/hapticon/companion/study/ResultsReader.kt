package org.hapticon.companion.study

import java.io.Reader
import java.io.StringReader
import org.hapticon.study.analysis.StudyResponse
import org.hapticon.study.export.Csv
import org.hapticon.study.export.CsvFormatException

/**
 * The tolerant reader `hapticon analyze` uses: any long-format results CSV with (at least) the columns
 * participant, task, icon and response, in any order; other columns are ignored.
 */
object ResultsReader {
    /** The columns the analysis needs. */
    val REQUIRED_COLUMNS: List<String> = listOf("participant", "task", "icon", "response")

    /** The responses in [text]; [CsvFormatException] naming [source] and the line of the first problem. */
    fun read(text: String, source: String): List<StudyResponse> = read(StringReader(text), source)

    /**
     * The responses of [reader], read record by record (the text is never held whole). Equal participant,
     * task and icon names share one String, so a million rows of a few hundred names stay small.
     */
    fun read(reader: Reader, source: String): List<StudyResponse> {
        val responses = ArrayList<StudyResponse>()
        val names = HashMap<String, String>()
        fun shared(name: String): String = names.putIfAbsent(name, name) ?: name
        var index: IntArray? = null
        var width = 0
        Csv.forEachRecord(reader, source) { record ->
            val columns = index
            if (columns == null) {
                val header = record.fields.map { it.trim() }
                val found = REQUIRED_COLUMNS.associateWith { header.indexOf(it) }
                val missing = found.filterValues { it < 0 }.keys
                if (missing.isNotEmpty()) throw CsvFormatException(source, record.line, "missing column${if (missing.size > 1) "s" else ""} ${missing.joinToString(", ")}")
                index = IntArray(REQUIRED_COLUMNS.size) { found.getValue(REQUIRED_COLUMNS[it]) }
                width = header.size
                return@forEachRecord
            }
            if (record.fields.size != width) {
                throw CsvFormatException(source, record.line, "expected $width fields as in the header, found ${record.fields.size}")
            }
            for (k in 0 until 3) {
                if (record.fields[columns[k]].isBlank()) throw CsvFormatException(source, record.line, "empty ${REQUIRED_COLUMNS[k]}")
            }
            val text = record.fields[columns[3]].trim()
            // Decimal notation only: Kotlin's toDouble also reads "4d" and the hex float "0x1p3" (= 8).
            val response = text.takeIf { DECIMAL.matches(it) }?.toDoubleOrNull()?.takeIf { it.isFinite() }
                ?: throw CsvFormatException(source, record.line, "response '$text' is not a finite decimal number")
            responses += StudyResponse(shared(record.fields[columns[0]]), shared(record.fields[columns[1]]), shared(record.fields[columns[2]]), response)
        }
        if (index == null) throw CsvFormatException(source, 1, "empty file: expected a header with ${REQUIRED_COLUMNS.joinToString(", ")}")
        return responses
    }

    private val DECIMAL = Regex("[+-]?(?:[0-9]+(?:\\.[0-9]*)?|\\.[0-9]+)(?:[eE][+-]?[0-9]+)?")
}
