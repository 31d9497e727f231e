package org.hapticon.companion

import org.hapticon.companion.cli.writeWav
import org.hapticon.companion.cli.PatternSource
import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.DEFAULT_SAMPLE_RATE
import org.hapticon.companion.cli.FORMAT_CHOICES
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.hapticon.companion.cli.cliName
import org.hapticon.core.io.WavEncoding
import org.hapticon.core.io.WavWriter
import org.hapticon.core.pattern.FrequencyMapping
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternFiles
import org.hapticon.core.pattern.PatternFormat
import org.hapticon.core.pattern.signal
import org.hapticon.core.render.stream
import java.io.File
import java.util.Locale

/**
 * `hapticon convert IN OUT [--range MIN_HZ:MAX_HZ] [--rate HZ] [--format f32|s16]`: a preset, icon, pattern,
 * AHAP or `.haptic` file into a `.json` pattern, `.ahap`, `.haptic` or a `.wav` rendering; formats come from
 * the extensions. What a format could not keep is printed, one `note:` line each, on stderr.
 */
fun runConvert(args: List<String>, console: Console) {
    val arguments = Arguments.parse("convert", args, valueOptions = setOf("range", "rate", "format"))
    val paths = arguments.positionals
    if (paths.size != 2) throw UsageException("convert needs IN and OUT, got ${paths.size} argument(s)")
    val (input, output) = paths
    val mapping = arguments.value("range")?.let(::parseRange) ?: FrequencyMapping.DEFAULT
    val imported = PatternSource.load(input, mapping)
    val out = File(output)
    val notes = imported.notes.toMutableList()
    val summary = if (out.name.lowercase().endsWith(".wav")) {
        writeWav(imported.pattern, out, arguments.int("rate", DEFAULT_SAMPLE_RATE), arguments.choice("format", FORMAT_CHOICES, WavEncoding.FLOAT32), mapping)
    } else {
        val format = PatternFormat.ofFileName(output)
            ?: throw UsageException("cannot tell the format of $output: expected .json, .ahap, .haptic or .wav")
        val export = PatternFiles.write(imported.pattern, format, mapping)
        notes += export.notes
        OutputFiles.write(out) { it.write(export.text.toByteArray()) }
        String.format(Locale.ROOT, "wrote %s: %s as %s, %.3f s, %d amplitude keys, %d transients", out, imported.pattern.name,
            format.name.lowercase(), imported.pattern.duration, imported.pattern.amplitude.size, imported.pattern.transients.size)
    }
    notes.forEach { console.err.println("hapticon: note: $it") }
    console.out.println(summary)
}

private fun parseRange(text: String): FrequencyMapping {
    val parts = text.split(':')
    val min = parts.getOrNull(0)?.toDoubleOrNull()
    val max = parts.getOrNull(1)?.toDoubleOrNull()
    if (parts.size != 2 || min == null || max == null || !(min > 0.0) || !(max > min) || !max.isFinite()) {
        throw UsageException("--range must be MIN_HZ:MAX_HZ with 0 < MIN < MAX, was '$text'")
    }
    return FrequencyMapping(min, max)
}
