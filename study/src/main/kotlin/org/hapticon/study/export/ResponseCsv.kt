package org.hapticon.study.export

/**
 * [ResponseRow]s as long-format CSV (RFC 4180: comma-separated, CRLF line ends, fields holding a comma, quote or line
 * break quoted with `"` and inner quotes doubled), under exactly the header [HEADER]. Absent values (text, sticker,
 * response time) are empty fields.
 */
public object ResponseCsv {
    /** The header line, without its line end. */
    public const val HEADER: String =
        "study_id,protocol_version,envelope_model,participant,participant_index,task,task_position,trial,stimulus,icon,text,sticker," +
            "question,response,response_time_ms,icon_presses,answered_at"

    private val COLUMNS = HEADER.split(',')

    /**
     * [rows] as CSV text: the header, then one line per row, every line ending in CRLF. With [forSpreadsheet] every
     * cell that a spreadsheet would run as a formula is [neutralised][CsvInjection.neutralise] (for files people
     * open; [read] would then return the quoted text, so uploads and round trips use the plain form). Does not throw.
     */
    public fun write(rows: List<ResponseRow>, forSpreadsheet: Boolean = false): String {
        val out = StringBuilder(HEADER).append("\r\n")
        for (row in rows) {
            val fields = listOf(
                row.studyId, row.protocolVersion.toString(), row.envelopeModel, row.participant, row.participantIndex.toString(), row.task,
                row.taskPosition.toString(), row.trial.toString(), row.stimulus, row.icon, row.text.orEmpty(), row.sticker.orEmpty(),
                row.question, row.response.toString(), row.responseTimeMillis?.toString().orEmpty(), row.iconPresses.toString(),
                row.answeredAtMillis.toString(),
            )
            fields.joinTo(out, ",") { Csv.quote(if (forSpreadsheet) CsvInjection.neutralise(it) else it) }
            out.append("\r\n")
        }
        return out.toString()
    }

    /**
     * The rows of [csv], which may end lines in CRLF or LF and may lack the last line end. Throws
     * [IllegalArgumentException] naming the line and column when the header is not exactly [HEADER], a record has the
     * wrong number of fields, a number does not parse, a quote is unterminated, or the text is empty.
     */
    public fun read(csv: String): List<ResponseRow> {
        val records = try {
            Csv.parse(csv, "csv").map { it.line to it.fields }
        } catch (e: CsvFormatException) {
            val problem = when (e.kind) {
                CsvProblem.TEXT_AFTER_QUOTE -> "text after a closing quote"
                else -> e.problem
            }
            throw IllegalArgumentException("line ${e.line}: $problem")
        }
        require(records.isNotEmpty()) { "empty CSV: expected the header $HEADER" }
        val (headerLine, header) = records[0]
        require(header == COLUMNS) { "line $headerLine: header must be exactly $HEADER" }
        return records.drop(1).map { (line, fields) ->
            require(fields.size == COLUMNS.size) { "line $line: expected ${COLUMNS.size} fields, got ${fields.size}" }
            val record = Record(line, fields)
            ResponseRow(
                studyId = record.text(0),
                protocolVersion = record.int(1),
                envelopeModel = record.text(2),
                participant = record.text(3),
                participantIndex = record.int(4),
                task = record.text(5),
                taskPosition = record.int(6),
                trial = record.int(7),
                stimulus = record.text(8),
                icon = record.text(9),
                text = record.optionalText(10),
                sticker = record.optionalText(11),
                question = record.text(12),
                response = record.int(13),
                responseTimeMillis = record.optionalLong(14),
                iconPresses = record.int(15),
                answeredAtMillis = record.long(16),
            )
        }
    }

    private class Record(val line: Int, val fields: List<String>) {
        fun text(i: Int): String = fields[i].ifEmpty { fail(i, "must not be empty") }

        fun optionalText(i: Int): String? = fields[i].ifEmpty { null }

        fun int(i: Int): Int = fields[i].toIntOrNull() ?: fail(i, "expected an integer, got '${fields[i].take(40)}'")

        fun long(i: Int): Long = optionalLong(i) ?: fail(i, "expected an integer, got ''")

        fun optionalLong(i: Int): Long? {
            if (fields[i].isEmpty()) return null
            return fields[i].toLongOrNull() ?: fail(i, "expected an integer, got '${fields[i].take(40)}'")
        }

        private fun fail(i: Int, message: String): Nothing = throw IllegalArgumentException("line $line, column ${COLUMNS[i]}: $message")
    }
}
