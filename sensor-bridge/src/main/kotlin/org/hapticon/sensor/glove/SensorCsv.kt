package org.hapticon.sensor.glove

/**
 * A sensor CSV could not be read: [source] (a file name or `csv`) line [lineNumber] (1-based, counting every
 * line including the header, blanks and comments) is wrong; the message reads `source:line: what is wrong`.
 */
public class SensorCsvException(
    public val source: String,
    public val lineNumber: Int,
    public val detail: String,
) : IllegalArgumentException("$source:$lineNumber: $detail")

/** One data row of a sensor CSV: its 1-based [lineNumber] and its numeric [values]. */
internal class CsvRow(val lineNumber: Int, val values: DoubleArray)

/**
 * The CSV dialect shared by the sensor files: comma-separated, a header line first, then numbers (parsed
 * with [String.toDouble], so `1e-3` works and no thousands separators do). Blank lines and lines starting with
 * `#` are skipped anywhere. Every number must be finite; the first column is a time in seconds that must
 * increase strictly from row to row.
 *
 * [headers] lists the accepted headers (compared trimmed, case-insensitive, spaces around commas ignored);
 * returns the index of the header found and the rows.
 * @throws SensorCsvException naming the first bad line.
 */
internal fun readSensorCsv(text: String, source: String, headers: List<List<String>>): Pair<Int, List<CsvRow>> {
    var headerIndex = -1
    var columns = 0
    val rows = ArrayList<CsvRow>()
    var previousTime = Double.NEGATIVE_INFINITY
    text.lineSequence().forEachIndexed { index, raw ->
        val lineNumber = index + 1
        val line = raw.trim()
        if (line.isEmpty() || line.startsWith("#")) return@forEachIndexed
        val cells = line.split(',').map { it.trim() }
        if (headerIndex < 0) {
            val lower = cells.map { it.lowercase() }
            headerIndex = headers.indexOf(lower)
            if (headerIndex < 0) {
                throw SensorCsvException(source, lineNumber, "expected a header ${headers.joinToString(" or ") { it.joinToString(",") }}, got \"$line\"")
            }
            columns = headers[headerIndex].size
            return@forEachIndexed
        }
        if (cells.size != columns) {
            throw SensorCsvException(source, lineNumber, "expected $columns columns (${headers[headerIndex].joinToString(",")}), got ${cells.size}")
        }
        val values = DoubleArray(columns)
        for (c in 0 until columns) {
            val value = cells[c].toDoubleOrNull()
                ?: throw SensorCsvException(source, lineNumber, "${headers[headerIndex][c]} is not a number: \"${cells[c]}\"")
            if (!value.isFinite()) throw SensorCsvException(source, lineNumber, "${headers[headerIndex][c]} must be finite, was ${cells[c]}")
            values[c] = value
        }
        if (values[0] <= previousTime) {
            throw SensorCsvException(source, lineNumber, "time must increase, ${values[0]} s after $previousTime s")
        }
        previousTime = values[0]
        rows += CsvRow(lineNumber, values)
    }
    if (headerIndex < 0) {
        throw SensorCsvException(source, 1, "no header: expected ${headers.joinToString(" or ") { it.joinToString(",") }}")
    }
    return headerIndex to rows
}
