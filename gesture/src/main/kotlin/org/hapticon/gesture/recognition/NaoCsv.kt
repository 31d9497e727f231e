package org.hapticon.gesture.recognition

/**
 * Reads one person's session in the layout of the NAO paper's published data: one row per 40 Hz sample with
 * four time-varying resistances and the gesture being performed.
 *
 * Header (names case-insensitive, any order): one time column (`time`, `time_s` or `timestamp`, seconds), four
 * resistance columns (names starting with `r`, e.g. `r1..r4` or `resistance1..4`, taken in header order), and
 * optionally a `label` (or `gesture`) column holding `hit-gentle` … `tickle-energetic` (or `hit_gentle`), with
 * `none`, `-` or empty for rest. Consecutive rows with the same label become one [NaoSpan]. We could not
 * fetch the published files while writing this, so the column names are accepted loosely rather than pinned;
 * the structure (time, four resistances, label) is the paper's.
 *
 * Errors are [IllegalArgumentException]s naming the line.
 */
public object NaoCsv {
    /** The session of [person] in [text]. */
    public fun read(text: String, person: String): NaoRecording {
        val lines = text.lineSequence().withIndex().filter { it.value.isNotBlank() && !it.value.startsWith("#") }.toList()
        require(lines.isNotEmpty()) { "line 1: expected a header with a time column and four resistance columns" }
        val header = lines[0].value.split(',').map { it.trim().lowercase() }
        val time = header.indexOfFirst { it == "time" || it == "time_s" || it == "timestamp" }
        val resistances = header.indices.filter { it != time && header[it].startsWith("r") }
        val label = header.indexOfFirst { it == "label" || it == "gesture" }
        val at = lines[0].index + 1
        require(time >= 0) { "line $at: no time column in ${header.joinToString(",")}" }
        require(resistances.size == NaoPreset.CHANNELS) { "line $at: expected ${NaoPreset.CHANNELS} resistance columns, found ${resistances.size}" }
        val rows = lines.drop(1)
        val channels = List(NaoPreset.CHANNELS) { DoubleArray(rows.size) }
        val labels = arrayOfNulls<String>(rows.size)
        var lastTime = Double.NEGATIVE_INFINITY
        rows.forEachIndexed { r, line ->
            val cells = line.value.split(',').map { it.trim() }
            val n = line.index + 1
            require(cells.size == header.size) { "line $n: expected ${header.size} fields, got ${cells.size}" }
            val t = cells[time].toDoubleOrNull()
            require(t != null && t.isFinite() && t > lastTime) { "line $n: time must be a number after the previous row's, was \"${cells[time]}\"" }
            lastTime = t
            resistances.forEachIndexed { c, column ->
                val v = cells[column].toDoubleOrNull()
                require(v != null && v.isFinite() && v >= 0.0) { "line $n: resistance ${header[column]} must be a finite number >= 0, was \"${cells[column]}\"" }
                channels[c][r] = v
            }
            if (label >= 0) {
                val id = cells[label].lowercase().replace('_', '-')
                labels[r] = if (id.isEmpty() || id == "-" || id == NaoPreset.NONE) null else id.also {
                    require(it in NaoPreset.LABELS) { "line $n: unknown gesture '${cells[label]}'; expected one of ${NaoPreset.LABELS.joinToString()}" }
                }
            }
        }
        val spans = ArrayList<NaoSpan>()
        var start = 0
        for (i in 1..rows.size) {
            if (i == rows.size || labels[i] != labels[start]) {
                labels[start]?.let { spans += NaoSpan(start, i, it) }
                start = i
            }
        }
        return NaoRecording(person, channels, spans)
    }
}
