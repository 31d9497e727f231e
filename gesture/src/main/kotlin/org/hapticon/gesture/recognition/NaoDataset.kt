package org.hapticon.gesture.recognition

import java.io.File

/**
 * Reads the NAO study's recordings in the layout its paper describes for the published dataset
 * (004_7d5078645d142b2a.txt:121, :162, :166): per participant, the raw resistances of the four sensors at 40 Hz, and
 * the start and end index of every kept gesture performance, paired with the pre-generated order that says which
 * gesture, intensity and sensor each one was. 117 of the 1800 performances were discarded for electrical shorts
 * (:166), so a participant may have fewer than 120; samples outside every performance are `none`.
 *
 * The paper names what is published, not the files' columns, so the two files' format is ours (a published file in
 * other columns converts with a spreadsheet):
 *
 * - `PERSON-raw.csv`: a header, then one row per 40 Hz sample; the columns `hand`, `lower_arm`, `upper_arm` and
 *   `shoulder` (any order, case and `_`/`-`/space ignored) hold each sensor's resistance (≥ 0, any one unit); other
 *   columns (a time, a marker) are ignored.
 * - `PERSON-indices.csv`: the header `start,end,gesture,intensity,location`, then one row per performance: 0-based
 *   sample indices into the raw rows (`end` exclusive), the gesture (`hit`/`hitting`, `poke`/`poking`, `squeeze`/
 *   `squeezing`, `stroke`/`stroking`, `tickle`/`tickling`), `gentle` or `energetic`, and the sensor it was performed
 *   on (a raw column's name).
 *
 * Errors are [IllegalArgumentException]s naming the file and line. Blank lines and `#` comments are skipped.
 */
public object NaoDataset {
    /** The raw columns, in [NaoPreset.LOCATIONS] order. */
    public val RAW_COLUMNS: List<String> = listOf("hand", "lower_arm", "upper_arm", "shoulder")

    /** The header of an index file. */
    public const val INDEX_HEADER: String = "start,end,gesture,intensity,location"

    /** One participant's recording from the texts of their raw and index files ([rawName], [indexName] name them in errors). */
    public fun read(person: String, raw: String, indices: String, rawName: String = "$person-raw.csv", indexName: String = "$person-indices.csv"): NaoRecording {
        val channels = readRaw(raw, rawName)
        val spans = readIndices(indices, indexName, channels[0].size)
        return NaoRecording(person, channels, spans)
    }

    /** Every participant in [dir]: each `PERSON-raw.csv` with its `PERSON-indices.csv`, by person name. */
    public fun readDirectory(dir: File): List<NaoRecording> {
        require(dir.isDirectory) { "$dir is not a directory" }
        val raws = dir.listFiles { f -> f.isFile && f.name.endsWith(RAW_SUFFIX) }.orEmpty().sortedBy { it.name }
        require(raws.isNotEmpty()) { "$dir holds no *$RAW_SUFFIX file" }
        return raws.map { raw ->
            val person = raw.name.removeSuffix(RAW_SUFFIX)
            val indices = File(dir, person + INDEX_SUFFIX)
            require(indices.isFile) { "$raw has no ${indices.name} beside it" }
            read(person, raw.readText(), indices.readText(), raw.path, indices.path)
        }
    }

    private const val RAW_SUFFIX = "-raw.csv"
    private const val INDEX_SUFFIX = "-indices.csv"

    private fun key(name: String): String = name.trim().lowercase().replace('-', '_').replace(' ', '_')

    private fun rows(text: String): List<IndexedValue<String>> =
        text.lineSequence().withIndex().filter { it.value.isNotBlank() && !it.value.trimStart().startsWith("#") }.toList()

    private fun readRaw(text: String, name: String): List<DoubleArray> {
        val lines = rows(text)
        require(lines.isNotEmpty()) { "$name: empty; expected a header with the columns ${RAW_COLUMNS.joinToString()}" }
        val header = lines[0].value.split(',').map(::key)
        val columns = RAW_COLUMNS.map { c -> header.indexOf(c) }
        val missing = RAW_COLUMNS.filterIndexed { i, _ -> columns[i] < 0 }
        require(missing.isEmpty()) { "$name:${lines[0].index + 1}: no column ${missing.joinToString(", ")} in ${lines[0].value.trim()}" }
        val data = lines.drop(1)
        val channels = List(NaoPreset.CHANNELS) { DoubleArray(data.size) }
        data.forEachIndexed { r, line ->
            val cells = line.value.split(',')
            val at = "$name:${line.index + 1}"
            require(cells.size == header.size) { "$at: expected ${header.size} fields, got ${cells.size}" }
            columns.forEachIndexed { c, column ->
                val v = cells[column].trim().toDoubleOrNull()
                require(v != null && v.isFinite() && v >= 0.0) { "$at: ${RAW_COLUMNS[c]} must be a finite resistance >= 0, was \"${cells[column].trim()}\"" }
                channels[c][r] = v
            }
        }
        return channels
    }

    private fun readIndices(text: String, name: String, samples: Int): List<NaoSpan> {
        val lines = rows(text)
        require(lines.isNotEmpty() && lines[0].value.split(',').map(::key) == INDEX_HEADER.split(',')) {
            "$name:${lines.firstOrNull()?.index?.plus(1) ?: 1}: expected the header $INDEX_HEADER"
        }
        var previousEnd = 0
        return lines.drop(1).map { line ->
            val cells = line.value.split(',').map { it.trim() }
            val at = "$name:${line.index + 1}"
            require(cells.size == 5) { "$at: expected 5 fields ($INDEX_HEADER), got ${cells.size}" }
            val start = cells[0].toIntOrNull()
            val end = cells[1].toIntOrNull()
            require(start != null && end != null && start >= previousEnd && start < end && end <= samples) {
                "$at: need $previousEnd <= start < end <= $samples (the raw file's rows, performances in order), was ${cells[0]}, ${cells[1]}"
            }
            previousEnd = end
            val gesture = GESTURE_NAMES[cells[2].lowercase()]
            require(gesture != null) { "$at: unknown gesture '${cells[2]}'; expected one of ${NaoPreset.GESTURES.joinToString()}" }
            val intensity = cells[3].lowercase()
            require(intensity in NaoPreset.INTENSITIES) { "$at: unknown intensity '${cells[3]}'; expected gentle or energetic" }
            val location = RAW_COLUMNS.indexOf(key(cells[4]))
            require(location >= 0) { "$at: unknown location '${cells[4]}'; expected one of ${RAW_COLUMNS.joinToString()}" }
            NaoSpan(start, end, "$gesture-$intensity", NaoPreset.LOCATIONS[location])
        }
    }

    /** The paper's gerunds (004_7d5078645d142b2a.txt:149) and our names, to ours. */
    private val GESTURE_NAMES: Map<String, String> =
        NaoPreset.GESTURES.associateWith { it } + mapOf("hitting" to "hit", "poking" to "poke", "squeezing" to "squeeze", "stroking" to "stroke", "tickling" to "tickle")
}
