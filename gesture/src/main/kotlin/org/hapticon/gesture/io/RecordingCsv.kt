package org.hapticon.gesture.io

import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import java.util.Locale
import kotlin.math.abs

/**
 * Reads and writes a [Recording] as CSV: a header `time_s,<channel>[,<channel>..]`, then one row per frame.
 *
 * A channel name may end in a unit, `force_N` → channel `force` in `N`; the units recognised are listed in
 * [UNITS] (anything else is part of the name and the unit is ""). The sample rate comes from the time
 * column: rows must be evenly spaced, each step within [TIMING_TOLERANCE] of the median step, or the file is
 * rejected naming the first late or early row. Non-finite or blank cells are handled by [GapPolicy].
 */
public object RecordingCsv {
    /** Unit suffixes recognised after the last `_` of a channel name. */
    public val UNITS: Set<String> = setOf("N", "V", "deg", "g", "px", "mV", "ms2", "Pa")

    /** Largest allowed deviation of one time step from the mean step, as a fraction of the mean step. */
    public const val TIMING_TOLERANCE: Double = 0.01

    /** What to do with a NaN, infinite or blank sample cell. */
    public enum class GapPolicy {
        /** Reject the file with the line of the first bad cell (the default: a gap is usually a broken export). */
        REJECT,

        /**
         * Fill each run of bad cells by linear interpolation between the good samples on either side; a run
         * at the start or end takes the nearest good sample. A channel with no good sample is still rejected.
         */
        INTERPOLATE,
    }

    /**
     * Parses [text]; [source] names the file in error messages (`source:line: problem`). Throws
     * [RecordingFormatException] for a bad header, a row with the wrong number of cells, an unparsable or
     * non-increasing time, irregular timing, fewer than 2 rows, or (under [GapPolicy.REJECT]) a bad cell.
     */
    public fun read(text: String, source: String = "recording.csv", gaps: GapPolicy = GapPolicy.REJECT): Recording {
        val lines = text.lineSequence().withIndex().filter { it.value.isNotBlank() }.toList()
        if (lines.isEmpty()) throw RecordingFormatException("$source: empty file, expected a header time_s,<channel>..")
        val header = lines.first().value.trim().removePrefix("\uFEFF").split(',').map { it.trim() }
        val headerLine = lines.first().index + 1
        if (header.first() != "time_s") fail(source, headerLine, "first column must be time_s, was '${header.first()}'")
        if (header.size < 2) fail(source, headerLine, "need at least one channel after time_s")
        val names = header.drop(1)
        names.forEachIndexed { i, name -> if (name.isEmpty()) fail(source, headerLine, "column ${i + 2} has no name") }
        if (names.toSet().size != names.size) fail(source, headerLine, "duplicate channel names in ${names.joinToString(",")}")

        val rows = lines.drop(1)
        if (rows.size < 2) fail(source, headerLine, "need at least 2 rows to know the sample rate, found ${rows.size}")
        val times = DoubleArray(rows.size)
        val columns = Array(names.size) { DoubleArray(rows.size) }
        val lineNumbers = IntArray(rows.size)
        for ((r, row) in rows.withIndex()) {
            val line = row.index + 1
            lineNumbers[r] = line
            val cells = row.value.split(',')
            if (cells.size != header.size) fail(source, line, "expected ${header.size} cells, found ${cells.size}")
            val time = cells[0].trim().toDoubleOrNull()
            if (time == null || !time.isFinite()) fail(source, line, "time_s '${cells[0].trim()}' is not a finite number")
            times[r] = time
            for (c in names.indices) {
                val cell = cells[c + 1].trim()
                val value = cell.toDoubleOrNull()
                if (value == null && cell.isNotEmpty() && cell.lowercase() !in NON_FINITE) {
                    fail(source, line, "${names[c]} '${cells[c + 1].trim()}' is not a number")
                }
                val sample = value ?: Double.NaN
                if (!sample.isFinite() && gaps == GapPolicy.REJECT) {
                    fail(source, line, "${names[c]} is ${if (cells[c + 1].isBlank()) "blank" else cells[c + 1].trim()}; gaps are rejected (fill them, or read with GapPolicy.INTERPOLATE)")
                }
                columns[c][r] = sample
            }
        }
        val sampleRate = sampleRate(times, lineNumbers, source)
        val channels = names.mapIndexed { c, name ->
            val (base, unit) = splitUnit(name)
            if (gaps == GapPolicy.INTERPOLATE && !fillGaps(columns[c])) {
                fail(source, headerLine, "channel $name has no finite sample to interpolate from")
            }
            Channel(base, unit, columns[c])
        }
        if (channels.map { it.name }.toSet().size != channels.size) {
            fail(source, headerLine, "channel names collide once units are split off: ${names.joinToString(",")}")
        }
        return Recording(sampleRate, channels)
    }

    /**
     * [recording] as CSV text that [read] reads back: time `i / sampleRate` and every sample with full
     * double precision (Kotlin's shortest round-trip form), channel names with their unit suffix.
     */
    public fun write(recording: Recording): String {
        val out = StringBuilder()
        out.append("time_s")
        for (channel in recording.channels) out.append(',').append(if (channel.unit.isEmpty()) channel.name else "${channel.name}_${channel.unit}")
        out.append('\n')
        for (i in 0 until recording.frameCount) {
            out.append((i / recording.sampleRate).toString())
            for (channel in recording.channels) out.append(',').append(channel[i].toString())
            out.append('\n')
        }
        return out.toString()
    }

    /** `force_N` → (`force`, `N`); a name without a recognised unit suffix keeps its name and gets unit "". */
    internal fun splitUnit(name: String): Pair<String, String> {
        val cut = name.lastIndexOf('_')
        if (cut <= 0) return name to ""
        val unit = name.substring(cut + 1)
        return if (unit in UNITS) name.substring(0, cut) to unit else name to ""
    }

    /** Spellings of a non-finite cell, which are gaps rather than typos. */
    private val NON_FINITE = setOf("nan", "inf", "+inf", "-inf", "infinity", "+infinity", "-infinity")

    private fun sampleRate(times: DoubleArray, lines: IntArray, source: String): Double {
        val meanStep = (times.last() - times.first()) / (times.size - 1)
        if (!(meanStep > 0.0)) fail(source, lines[1], "time_s must increase, ${times.first()} to ${times.last()} does not")
        // Steps are compared with the median, not the mean, so the row reported is the odd one out.
        val steps = DoubleArray(times.size - 1) { times[it + 1] - times[it] }
        val typical = steps.sortedArray()[steps.size / 2]
        for (i in steps.indices) {
            if (abs(steps[i] - typical) > TIMING_TOLERANCE * typical) {
                fail(
                    source, lines[i + 1],
                    String.format(Locale.ROOT, "irregular timing: step %.6g s from the previous row, the typical (median) step is %.6g s", steps[i], typical),
                )
            }
        }
        return 1.0 / meanStep
    }

    /** Linear interpolation over non-finite runs in place; false when no sample is finite. */
    private fun fillGaps(samples: DoubleArray): Boolean {
        val firstGood = samples.indexOfFirst { it.isFinite() }
        if (firstGood < 0) return false
        var previous = -1
        for (i in samples.indices) {
            if (!samples[i].isFinite()) continue
            if (previous < 0) {
                for (j in 0 until i) samples[j] = samples[i]
            } else if (i - previous > 1) {
                val a = samples[previous]
                val b = samples[i]
                for (j in previous + 1 until i) samples[j] = a + (b - a) * (j - previous) / (i - previous)
            }
            previous = i
        }
        for (j in previous + 1 until samples.size) samples[j] = samples[previous]
        return true
    }

    private fun fail(source: String, line: Int, problem: String): Nothing = throw RecordingFormatException("$source:$line: $problem")
}

/** A recording file that cannot be read; the message names the file and, for CSV, the line. */
public class RecordingFormatException(message: String) : IllegalArgumentException(message)
