package org.hapticon.companion.sensors

import org.hapticon.sensor.grains.FsrForceConverter
import org.hapticon.sensor.grains.GrainCsv
import org.hapticon.sensor.grains.GrainOnsets
import org.hapticon.sensor.grains.GrainSettings
import java.util.Locale

/** What `hapticon grains` computed for a recording read as [GrainCsv] reads it. */
class GrainTable(val summary: GrainOnsets) {
    /** The table as CSV: the header `onset_s,bin,force_n`, then one grain per line (6, 0 and 4 decimals), locale-independent. */
    fun format(): String = buildString {
        append(HEADER).append('\n')
        for (grain in summary.grains) {
            append(String.format(Locale.ROOT, "%.6f,%d,%.4f", grain.timeSeconds, grain.bin, grain.filteredNewtons)).append('\n')
        }
    }

    companion object {
        /** The header line of [format]. */
        const val HEADER: String = "onset_s,bin,force_n"

        /**
         * The grains of the FSR recording [csv] (`time_s,force` or `time_s,voltage`), named [source] in errors.
         * @throws org.hapticon.sensor.glove.SensorCsvException naming [source] and the bad line.
         * @throws IllegalArgumentException when the recording's sample rate does not suit [settings].
         */
        fun compute(csv: String, settings: GrainSettings, source: String, converter: FsrForceConverter = FsrForceConverter()): GrainTable =
            GrainTable(GrainCsv.onsets(csv, settings, sampleRateHz = null, converter = converter, source = source))
    }
}
