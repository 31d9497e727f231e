package org.hapticon.sensor.grains

import org.hapticon.sensor.glove.SensorCsvException
import org.hapticon.sensor.glove.readSensorCsv
import java.util.Locale

/**
 * Where grains start in a force recording: [grains] in order, decided at [sampleRateHz] over [samples] rows,
 * with [grainSamples] samples per grain.
 */
public data class GrainOnsets(
    val grains: List<GrainOnset>,
    val sampleRateHz: Double,
    val samples: Int,
    val grainSamples: Int,
) {
    /** The time column of each sample at which a grain fires. */
    val onsetTimesSeconds: List<Double> get() = grains.map { it.timeSeconds }
}

/** One grain: its onset [timeSeconds] (the recording's time column), the force [bin] it fired for, and the filtered force then. */
public data class GrainOnset(val timeSeconds: Double, val bin: Int, val filteredNewtons: Double)

/**
 * The `hapticon grains` computation as a pure function: an FSR recording in, grain onset times out.
 *
 * The CSV has the header `time_s,force` (force in newtons) or `time_s,voltage` (the FSR divider's output in
 * volts, turned into newtons by an [FsrForceConverter]); times in seconds, strictly increasing. Blank lines
 * and `#` comments are skipped.
 */
public object GrainCsv {
    /** Header of a force recording. */
    public const val FORCE_HEADER: String = "time_s,force"

    /** Header of a voltage recording. */
    public const val VOLTAGE_HEADER: String = "time_s,voltage"

    /**
     * The grain onsets of the recording [csv] with [settings]. The filter and grain length need a sample rate:
     * [sampleRateHz] when given, otherwise the mean rate of the recording, (rows − 1)/(t_last − t_first)
     * (then at least 2 rows are needed). Voltage rows go through [converter].
     * @throws SensorCsvException naming [source] and the line for a malformed line, a non-finite or
     *   non-increasing value, a voltage the converter reports as a fault, or too few rows.
     * @throws IllegalArgumentException when the sample rate does not suit [settings] (cutoff ≥ fs/2).
     */
    public fun onsets(
        csv: String,
        settings: GrainSettings = GrainSettings(),
        sampleRateHz: Double? = null,
        converter: FsrForceConverter = FsrForceConverter(),
        source: String = "csv",
    ): GrainOnsets {
        val (header, rows) = readSensorCsv(csv, source, listOf(FORCE_HEADER.split(','), VOLTAGE_HEADER.split(',')))
        val forces = DoubleArray(rows.size)
        for ((i, row) in rows.withIndex()) {
            forces[i] = if (header == 0) {
                row.values[1]
            } else {
                when (val reading = converter.forceOf(row.values[1])) {
                    is FsrReading.Force -> reading.newtons
                    is FsrReading.Fault -> throw SensorCsvException(source, row.lineNumber, "FSR fault ${reading.fault} at ${reading.volts} V")
                }
            }
        }
        val rate = sampleRateHz ?: run {
            if (rows.size < 2) {
                val line = rows.lastOrNull()?.lineNumber ?: 1
                throw SensorCsvException(source, line, "need at least 2 samples to estimate the sample rate, got ${rows.size}")
            }
            (rows.size - 1) / (rows.last().values[0] - rows.first().values[0])
        }
        val decider = GrainDecider(settings, rate)
        val onsets = ArrayList<GrainOnset>()
        for (i in forces.indices) {
            if (decider.offer(forces[i])) onsets += GrainOnset(rows[i].values[0], decider.currentReferenceBin, decider.filteredNewtons)
        }
        return GrainOnsets(onsets, rate, rows.size, decider.grainSamples)
    }

    /** [onsets] as CSV: the header `onset_s`, then one time per line with 6 decimals, `\n` line ends, locale-independent. */
    public fun format(onsets: GrainOnsets): String = buildString {
        append("onset_s\n")
        for (time in onsets.onsetTimesSeconds) append(String.format(Locale.ROOT, "%.6f", time)).append('\n')
    }
}
