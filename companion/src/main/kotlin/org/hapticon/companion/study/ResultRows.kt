package org.hapticon.companion.study

import java.time.Instant
import java.time.OffsetDateTime
import java.time.format.DateTimeParseException

/** A row the collector refused: the 1-based [line] of the upload (0 for the request as a whole) and why. */
class InvalidUploadException(val line: Int, message: String) : Exception(message)

/**
 * One row of the long-format study results, every field as the text it was uploaded as (so a download
 * gives back exactly what was stored), in [ResultRows.HEADER] order.
 */
class ResultRow(val fields: List<String>) {
    init {
        require(fields.size == ResultRows.HEADER.size) { "a result row has ${ResultRows.HEADER.size} fields, got ${fields.size}" }
    }

    /** The field of column [name]. */
    operator fun get(name: String): String = fields[ResultRows.column(name)]

    /** The primary key (study_id, participant, task, trial): one row per trial. */
    val key: List<String> get() = listOf(this["study_id"], this["participant"], this["task"], this["trial"])

    override fun equals(other: Any?): Boolean = other is ResultRow && fields == other.fields
    override fun hashCode(): Int = fields.hashCode()
}

/** The rows of one upload and the line each started on. */
class ParsedUpload(val rows: List<ResultRow>, val lines: List<Int>)

/** The long-format results CSV as the collector accepts and serves it. */
object ResultRows {
    /** The header, exactly; the app writes these columns in this order. */
    val HEADER: List<String> = listOf(
        "study_id", "protocol_version", "envelope_model", "participant", "participant_index", "task", "task_position", "trial",
        "stimulus", "icon", "text", "sticker", "question", "response", "response_time_ms", "icon_presses", "answered_at",
    )

    /** Columns stored as integers, so downloads sort 2 before 10; their text must be canonical to round-trip. */
    val INTEGER_COLUMNS: Set<String> = setOf("participant_index", "task_position", "trial")

    private val COUNT_COLUMNS = setOf("participant_index", "task_position", "trial", "response_time_ms", "icon_presses")
    private val NON_EMPTY_COLUMNS = setOf("study_id", "protocol_version", "envelope_model", "participant", "task", "question")

    /** Index of column [name] in [HEADER]. */
    fun column(name: String): Int = HEADER.indexOf(name).also { require(it >= 0) { "no column $name" } }

    /**
     * The rows of an upload for [studyId]; [InvalidUploadException] naming the line of the first bad row:
     * a header other than [HEADER], a wrong field count, an empty required field, a study_id other than
     * [studyId], a count that is not a whole number ≥ 0, a response that is not a finite number, an
     * answered_at that is not an ISO-8601 instant, or no rows at all.
     */
    fun parse(text: String, studyId: String): ParsedUpload {
        val records = try {
            Csv.parse(text, "upload")
        } catch (e: CsvFormatException) {
            throw InvalidUploadException(e.line, "line ${e.line}: ${e.problem}")
        }
        val header = records.firstOrNull() ?: throw InvalidUploadException(1, "line 1: empty body, expected the header ${HEADER.joinToString(",")}")
        if (header.fields != HEADER) throw InvalidUploadException(header.line, "line ${header.line}: header must be exactly ${HEADER.joinToString(",")}")
        if (records.size == 1) throw InvalidUploadException(header.line, "line ${header.line}: no rows after the header")
        val rows = records.drop(1)
        return ParsedUpload(rows.map { validate(it, studyId) }, rows.map { it.line })
    }

    private fun validate(record: CsvRecord, studyId: String): ResultRow {
        fun fail(problem: String): Nothing = throw InvalidUploadException(record.line, "line ${record.line}: $problem")
        if (record.fields.size != HEADER.size) fail("expected ${HEADER.size} fields, found ${record.fields.size}")
        val row = ResultRow(record.fields)
        for (name in NON_EMPTY_COLUMNS) if (row[name].isBlank()) fail("empty $name")
        if (row["study_id"] != studyId) fail("study_id '${row["study_id"]}' does not match X-Study-Id '$studyId'")
        for (name in COUNT_COLUMNS) {
            val value = row[name].toLongOrNull()
            // Canonical digits only ("07" or "+7" would not read back the same from an INTEGER column).
            if (value == null || value < 0 || value.toString() != row[name]) fail("$name '${row[name]}' is not a whole number ≥ 0")
            if (name in INTEGER_COLUMNS && value > Int.MAX_VALUE) fail("$name '${row[name]}' is too large")
        }
        if (row["response"].toDoubleOrNull()?.isFinite() != true) fail("response '${row["response"]}' is not a finite number")
        if (!isInstant(row["answered_at"])) fail("answered_at '${row["answered_at"]}' is not an ISO-8601 time such as 2026-11-22T02:00:00Z")
        return row
    }

    private fun isInstant(text: String): Boolean = try {
        Instant.parse(text)
        true
    } catch (e: DateTimeParseException) {
        try {
            OffsetDateTime.parse(text)
            true
        } catch (e2: DateTimeParseException) {
            false
        }
    }

    /** [rows] as CSV text with [HEADER]. */
    fun format(rows: List<ResultRow>): String = Csv.line(HEADER) + rows.joinToString("") { Csv.line(it.fields) }

    /** Study ids are used in URLs and as keys: letters, digits, `.`, `_`, `-`, at most 64. */
    val STUDY_ID: Regex = Regex("[A-Za-z0-9._-]{1,64}")
}
