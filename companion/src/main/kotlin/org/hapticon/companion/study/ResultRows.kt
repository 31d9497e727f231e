package org.hapticon.companion.study

import java.time.Instant
import java.time.OffsetDateTime
import java.time.format.DateTimeParseException
import org.hapticon.study.LikertScale
import org.hapticon.study.export.Csv
import org.hapticon.study.export.CsvFormatException
import org.hapticon.study.export.CsvRecord

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

    /** Names and labels: printable on one line, no surrounding spaces (` P01` and `P01` would be two participants). */
    private val IDENTIFIER_COLUMNS = listOf("study_id", "protocol_version", "envelope_model", "participant", "task", "stimulus", "icon", "sticker")

    /** What people wrote or read: may hold line breaks and tabs, never other control characters. */
    private val FREE_TEXT_COLUMNS = listOf("text", "question")

    /** Columns holding numbers the collector validated: canonical digits, so they never start like a formula. */
    private val NUMBER_COLUMNS: Set<String> = COUNT_COLUMNS + "response"

    /** The widest item a Hapticon study asks: 1..[LikertScale.MAX_POINTS]. */
    val ANY_SCALE: IntRange = 1..LikertScale.MAX_POINTS

    /** Index of column [name] in [HEADER]. */
    fun column(name: String): Int = HEADER.indexOf(name).also { require(it >= 0) { "no column $name" } }

    /**
     * The rows of an upload for [studyId]; [InvalidUploadException] naming the line of the first bad row:
     * a header other than [HEADER], a wrong field count, an empty required field, a study_id other than
     * [studyId], a count that is not a whole number ≥ 0, a response that is not a whole decimal number in
     * [responses] (the item's scale: `4d`, `0x1p3`, ` 4 `, `+1`, `4.0` and `9` on a 1..5 item are all refused), an
     * identifier with a control or invisible formatting character or surrounding spaces, free text with a control
     * character other than a line break or tab, an answered_at that is not an ISO-8601 instant, or no rows at all.
     */
    fun parse(text: String, studyId: String, responses: IntRange = ANY_SCALE): ParsedUpload {
        val records = try {
            Csv.parse(text, "upload")
        } catch (e: CsvFormatException) {
            throw InvalidUploadException(e.line, "line ${e.line}: ${e.problem}")
        }
        val header = records.firstOrNull() ?: throw InvalidUploadException(1, "line 1: empty body, expected the header ${HEADER.joinToString(",")}")
        if (header.fields != HEADER) throw InvalidUploadException(header.line, "line ${header.line}: header must be exactly ${HEADER.joinToString(",")}")
        if (records.size == 1) throw InvalidUploadException(header.line, "line ${header.line}: no rows after the header")
        val rows = records.drop(1)
        return ParsedUpload(rows.map { validate(it, studyId, responses) }, rows.map { it.line })
    }

    private fun validate(record: CsvRecord, studyId: String, responses: IntRange): ResultRow {
        fun fail(problem: String): Nothing = throw InvalidUploadException(record.line, "line ${record.line}: $problem")
        if (record.fields.size != HEADER.size) fail("expected ${HEADER.size} fields, found ${record.fields.size}")
        val row = ResultRow(record.fields)
        for (name in NON_EMPTY_COLUMNS) if (row[name].isBlank()) fail("empty $name")
        for (name in IDENTIFIER_COLUMNS) {
            val value = row[name]
            unprintable(value, allowLineBreaks = false)?.let { fail("$name ${shown(value)} holds $it") }
            if (value.isNotEmpty() && (value.first().isWhitespace() || value.last().isWhitespace())) fail("$name ${shown(value)} starts or ends with a space")
        }
        for (name in FREE_TEXT_COLUMNS) unprintable(row[name], allowLineBreaks = true)?.let { fail("$name ${shown(row[name])} holds $it") }
        if (row["study_id"] != studyId) fail("study_id ${shown(row["study_id"])} does not match X-Study-Id '$studyId'")
        for (name in COUNT_COLUMNS) {
            val value = wholeNumber(row[name])
            if (value == null) fail("$name ${shown(row[name])} is not a whole number ≥ 0")
            if (name in INTEGER_COLUMNS && value > Int.MAX_VALUE) fail("$name ${shown(row[name])} is too large")
        }
        // Kotlin's toDouble is Java's Double.valueOf: it reads "4d", "0x1p3" (= 8) and " 4 ". Digits only.
        val response = wholeNumber(row["response"])
        if (response == null || response !in responses.first..responses.last) {
            fail("response ${shown(row["response"])} is not a whole number in ${responses.first}..${responses.last} (the item's scale)")
        }
        if (!isInstant(row["answered_at"])) fail("answered_at ${shown(row["answered_at"])} is not an ISO-8601 time such as 2026-11-22T02:00:00Z")
        return row
    }

    /**
     * [text] as canonical decimal digits (no sign, space, leading zero, exponent, suffix or hex: "07" or "+7" would not
     * read back the same from an INTEGER column), or null.
     */
    private fun wholeNumber(text: String): Long? =
        if (text.length in 1..18 && text.all { it in '0'..'9' } && (text == "0" || text[0] != '0')) text.toLong() else null

    /**
     * What makes [text] unfit for a results table, or null: a control character (NUL, ESC…; line breaks and tabs only
     * when [allowLineBreaks]), an invisible formatting character (bidirectional overrides, zero-width joiners) or
     * separator, or half a surrogate pair.
     */
    private fun unprintable(text: String, allowLineBreaks: Boolean): String? {
        for ((i, c) in text.withIndex()) {
            if (allowLineBreaks && (c == '\n' || c == '\r' || c == '\t')) continue
            val bad = when {
                Character.isISOControl(c) -> "a control character"
                Character.getType(c).toByte() in INVISIBLE -> "an invisible formatting character"
                Character.isHighSurrogate(c) && (i + 1 >= text.length || !Character.isLowSurrogate(text[i + 1])) -> "half a surrogate pair"
                Character.isLowSurrogate(c) && (i == 0 || !Character.isHighSurrogate(text[i - 1])) -> "half a surrogate pair"
                else -> null
            }
            if (bad != null) return "$bad (U+%04X at character ${i + 1})".format(c.code)
        }
        return null
    }

    private val INVISIBLE = setOf(Character.FORMAT, Character.LINE_SEPARATOR, Character.PARAGRAPH_SEPARATOR)

    /** [value] quoted for an error line, control characters as `\uXXXX`, at most 40 characters. */
    private fun shown(value: String): String {
        val cut = if (value.length > 40) value.take(40) + "…" else value
        return "'" + cut.map { if (Character.isISOControl(it) || Character.getType(it).toByte() in INVISIBLE) "\\u%04x".format(it.code) else it.toString() }.joinToString("") + "'"
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

    /**
     * [rows] as CSV text with [HEADER], for a spreadsheet: the numbers were validated as plain digits; every other cell
     * that starts like a formula (`=`, `+`, `-`, `@`, tab, CR) gets a leading `'` (OWASP), `+1` and `-2` included —
     * the exception [SpreadsheetCsv.neutralise] makes for signed numbers is for analysis tables, not for names and text.
     */
    fun format(rows: List<ResultRow>): String = SpreadsheetCsv.line(HEADER) + rows.joinToString("") { row ->
        row.fields.withIndex().joinToString(",", postfix = "\n") { (i, value) ->
            SpreadsheetCsv.field(if (HEADER[i] in NUMBER_COLUMNS) value else SpreadsheetCsv.neutraliseText(value))
        }
    }

    /** Study ids are used in URLs and as keys: letters, digits, `.`, `_`, `-`, at most 64. */
    val STUDY_ID: Regex = Regex("[A-Za-z0-9._-]{1,64}")
}
