package org.hapticon.companion.study

import org.hapticon.study.analysis.StudyResponse

/**
 * The tolerant reader `hapticon analyze` uses: any long-format results CSV with (at least) the columns
 * participant, task, icon and response, in any order; other columns are ignored.
 */
object ResultsReader {
    /** The columns the analysis needs. */
    val REQUIRED_COLUMNS: List<String> = listOf("participant", "task", "icon", "response")

    /** The responses in [text]; [CsvFormatException] naming [source] and the line of the first problem. */
    fun read(text: String, source: String): List<StudyResponse> {
        val records = Csv.parse(text, source)
        val header = records.firstOrNull() ?: throw CsvFormatException(source, 1, "empty file: expected a header with ${REQUIRED_COLUMNS.joinToString(", ")}")
        val names = header.fields.map { it.trim() }
        val index = REQUIRED_COLUMNS.associateWith { names.indexOf(it) }
        val missing = index.filterValues { it < 0 }.keys
        if (missing.isNotEmpty()) throw CsvFormatException(source, header.line, "missing column${if (missing.size > 1) "s" else ""} ${missing.joinToString(", ")}")
        return records.drop(1).map { record ->
            if (record.fields.size != names.size) {
                throw CsvFormatException(source, record.line, "expected ${names.size} fields as in the header, found ${record.fields.size}")
            }
            fun column(name: String) = record.fields[index.getValue(name)]
            for (name in listOf("participant", "task", "icon")) {
                if (column(name).isBlank()) throw CsvFormatException(source, record.line, "empty $name")
            }
            val text = column("response").trim()
            val response = text.toDoubleOrNull()?.takeIf { it.isFinite() }
                ?: throw CsvFormatException(source, record.line, "response '$text' is not a finite number")
            StudyResponse(column("participant"), column("task"), column("icon"), response)
        }
    }
}
