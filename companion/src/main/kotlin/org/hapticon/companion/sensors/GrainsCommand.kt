package org.hapticon.companion.sensors

import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.UsageException
import org.hapticon.sensor.grains.BinDistribution
import org.hapticon.sensor.grains.GrainSettings
import org.hapticon.sensor.glove.SensorCsvException
import java.util.Locale

/** `--distribution` values. */
val DISTRIBUTION_CHOICES: Map<String, BinDistribution> = BinDistribution.entries.associateByTo(LinkedHashMap()) { it.name.lowercase() }

/**
 * `hapticon grains --in FSR.csv [--grains N] [--distribution linear|convex|concave]`: the [GrainTable] CSV to
 * stdout, one line about the run to stderr.
 */
fun runGrains(args: List<String>, console: Console) {
    val arguments = Arguments.parse("grains", args, valueOptions = setOf("in", "grains", "distribution"))
    arguments.requireNoPositionals()
    val count = arguments.int("grains", GrainSettings.DEFAULT_GRAIN_COUNT)
    if (count !in GrainSettings.MIN_GRAIN_COUNT..GrainSettings.MAX_GRAIN_COUNT) {
        throw UsageException("--grains must be in ${GrainSettings.MIN_GRAIN_COUNT}..${GrainSettings.MAX_GRAIN_COUNT}, got $count")
    }
    val settings = GrainSettings(grainCount = count, distribution = arguments.choice("distribution", DISTRIBUTION_CHOICES, BinDistribution.LINEAR))
    val path = arguments.required("in")
    val csv = InputFiles.readText("in", path)
    val table = try {
        GrainTable.compute(csv, settings, source = path)
    } catch (e: SensorCsvException) {
        throw UsageException(e.message.orEmpty())
    } catch (e: IllegalArgumentException) {
        // The rows are fine but their rate is not (e.g. too slow for the 20 Hz filter).
        throw UsageException("$path: cannot decide grains at this sample rate: ${e.message}")
    }
    console.out.print(table.format())
    console.err.println(describe(table, settings))
}

/** The stderr line: how the grains were decided. */
internal fun describe(table: GrainTable, settings: GrainSettings): String {
    val summary = table.summary
    return String.format(
        Locale.ROOT, "grains: %d onsets from %d samples at %.1f Hz (mean rate of time_s), %d-sample grains, %d grains = %d %s bins over %s-%s N",
        table.summary.grains.size, summary.samples, summary.sampleRateHz, summary.grainSamples, settings.grainCount, settings.binCount,
        settings.distribution.name.lowercase(), number(settings.minNewtons), number(settings.maxNewtons),
    )
}

private fun number(value: Double): String = if (value == Math.rint(value)) value.toLong().toString() else value.toString()
