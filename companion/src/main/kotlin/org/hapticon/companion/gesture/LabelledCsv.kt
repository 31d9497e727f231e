package org.hapticon.companion.gesture

import org.hapticon.companion.cli.UsageException
import org.hapticon.gesture.Channel
import org.hapticon.gesture.Recording
import org.hapticon.gesture.recognition.GestureLabel
import org.hapticon.gesture.recognition.LabelledRecording
import org.hapticon.gesture.recognition.LabelledSpan

/**
 * Labelled gesture recordings as CSV: a header `time_s,<channel>...[,label]`, then one row per frame with the
 * time in seconds (strictly increasing; the sample rate is their mean rate) and one number per channel (an
 * empty cell or `nan` is a gap, which the features hold over). Labels are [GestureLabel] ids (`knock-gentle`,
 * `none`); with a `label` column each row carries its own, otherwise the file name must contain exactly one
 * label id (e.g. `p3-hug-energetic-2.csv`) and the whole file has that label. Units are not in the file:
 * channels are taken as `force` in N and anything else as given by the sensor.
 */
object LabelledCsv {
    /** [text] of file [name] as a recording with spans; [UsageException] `name:line: problem` when malformed. */
    fun parse(text: String, name: String, requireLabel: Boolean = true): LabelledRecording {
        val lines = text.lineSequence().map { it.trim() }.withIndex().filter { it.value.isNotEmpty() && !it.value.startsWith("#") }.toList()
        if (lines.isEmpty()) throw UsageException("$name: empty file, expected a header time_s,<channels>")
        val header = lines[0].value.split(',').map { it.trim() }
        if (header.firstOrNull() != "time_s") throw UsageException("$name:${lines[0].index + 1}: header must start with time_s, was '${header.firstOrNull()}'")
        val labelColumn = header.indexOf("label").takeIf { it >= 0 }
        val channelNames = header.drop(1).filter { it != "label" }
        if (channelNames.isEmpty()) throw UsageException("$name: no channel columns after time_s")
        if (channelNames.toSet().size != channelNames.size || channelNames.any { it.isEmpty() }) throw UsageException("$name: channel names must be unique and non-empty: $channelNames")
        val times = ArrayList<Double>()
        val values = channelNames.map { ArrayList<Double>() }
        val rowLabels = ArrayList<GestureLabel>()
        for ((index, line) in lines.drop(1)) {
            val cells = line.split(',').map { it.trim() }
            if (cells.size != header.size) throw UsageException("$name:${index + 1}: ${cells.size} cells, header has ${header.size}")
            val time = cells[0].toDoubleOrNull()?.takeIf { it.isFinite() } ?: throw UsageException("$name:${index + 1}: time_s '${cells[0]}' is not a finite number")
            if (times.isNotEmpty() && time <= times.last()) throw UsageException("$name:${index + 1}: time_s must increase, $time follows ${times.last()}")
            times += time
            var channel = 0
            for ((column, cell) in cells.withIndex()) {
                if (column == 0) continue
                if (column == labelColumn) {
                    rowLabels += GestureLabel.parseOrNull(cell) ?: throw UsageException("$name:${index + 1}: unknown label '$cell'; expected ${GestureLabel.ALL.joinToString { it.id }}")
                    continue
                }
                values[channel++] += if (cell.isEmpty() || cell.equals("nan", ignoreCase = true)) Double.NaN
                else cell.toDoubleOrNull() ?: throw UsageException("$name:${index + 1}: '${cell}' in ${header[column]} is not a number")
            }
        }
        if (times.size < 2) throw UsageException("$name: needs at least two rows to know the sample rate")
        val rate = (times.size - 1) / (times.last() - times.first())
        val recording = Recording(rate, channelNames.mapIndexed { i, n -> Channel(n, if (n == "force") "N" else "", values[i].toDoubleArray()) })
        val spans = when {
            labelColumn != null -> runs(rowLabels)
            requireLabel -> listOf(LabelledSpan(0, recording.frameCount, labelFromName(name)))
            else -> emptyList()
        }
        return LabelledRecording(recording, spans)
    }

    /** The one label id in file [name]; [UsageException] when there is none or more than one. */
    fun labelFromName(name: String): GestureLabel {
        val stem = name.substringAfterLast('/').substringBeforeLast('.').lowercase().replace('_', '-')
        val found = GestureLabel.ALL.filter { Regex("(^|[^a-z])${Regex.escape(it.id)}($|[^a-z])").containsMatchIn(stem) }
        return found.singleOrNull()
            ?: throw UsageException("$name: no label column, and the file name holds ${if (found.isEmpty()) "no" else "more than one"} label id (${GestureLabel.ALL.joinToString { it.id }})")
    }

    private fun runs(labels: List<GestureLabel>): List<LabelledSpan> {
        val spans = ArrayList<LabelledSpan>()
        var start = 0
        for (i in 1..labels.size) {
            if (i == labels.size || labels[i] != labels[start]) {
                if (!labels[start].isNone) spans += LabelledSpan(start, i, labels[start])
                start = i
            }
        }
        return spans
    }
}
