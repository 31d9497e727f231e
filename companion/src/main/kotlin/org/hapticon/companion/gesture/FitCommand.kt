package org.hapticon.companion.gesture

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.io.SchemaJson
import org.hapticon.core.io.shortNumber
import org.hapticon.companion.cli.Arguments
import org.hapticon.companion.cli.Console
import org.hapticon.companion.cli.OutputFiles
import org.hapticon.companion.cli.UsageException
import org.hapticon.core.io.IconJson
import org.hapticon.gesture.Recording
import org.hapticon.gesture.extraction.EnvelopeMethod
import org.hapticon.gesture.extraction.FitBenchmark
import org.hapticon.gesture.extraction.FitOptions
import org.hapticon.gesture.extraction.IconFit
import org.hapticon.gesture.extraction.IconFitter
import org.hapticon.gesture.extraction.LevelReference
import org.hapticon.gesture.io.RecordingCsv
import org.hapticon.gesture.io.RecordingFormatException
import org.hapticon.gesture.io.RecordingWav
import java.io.File
import java.io.IOException
import java.util.Locale

/** `--envelope` values. */
val ENVELOPE_CHOICES: Map<String, EnvelopeMethod> = linkedMapOf("lowpass" to EnvelopeMethod.LOWPASS, "rms" to EnvelopeMethod.RMS)

/** What `--reference` asked for: one fixed [LevelReference], or the strongest gesture of the batch. */
private sealed class ReferenceChoice {
    class Fixed(val reference: LevelReference) : ReferenceChoice()
    object Strongest : ReferenceChoice()
}

/** `--reference full-scale|peak|strongest|VALUE`; full-scale (the input's full scale) by default. */
private fun referenceOf(text: String?): ReferenceChoice = when (text) {
    null, "full-scale" -> ReferenceChoice.Fixed(LevelReference.FullScale)
    "peak" -> ReferenceChoice.Fixed(LevelReference.GesturePeak)
    "strongest" -> ReferenceChoice.Strongest
    else -> {
        val value = text.toDoubleOrNull()?.takeIf { it.isFinite() && it > 0.0 }
            ?: throw UsageException("--reference must be full-scale, peak, strongest or a number > 0, got '${text.take(40)}'")
        ReferenceChoice.Fixed(LevelReference.Value(value))
    }
}

/**
 * `hapticon fit --in REC.wav|REC.csv|DIR [--channel NAME] [--envelope lowpass|rms]
 * [--reference full-scale|peak|strongest|VALUE] [--name NAME] --out ICON.json|DIR [--json]`: fits an icon to the
 * recording, writes it as icon JSON, and prints the icon and its fit report (text, or one JSON object with
 * `--json`). The level is measured against the input's full scale unless `--reference` names another: a value in
 * the channel's units (e.g. a sensor's calibrated maximum), `peak` (the gesture's own peak: full strength), or
 * `strongest` (a batch: every `.wav`/`.csv` in the directory `--in`, written to the directory `--out`, the strongest
 * gesture being level 1).
 */
fun runFit(args: List<String>, console: Console) {
    val arguments = Arguments.parse("fit", args, valueOptions = setOf("in", "channel", "envelope", "reference", "name", "out"), flagOptions = setOf("json"))
    arguments.requireNoPositionals()
    val path = arguments.required("in")
    val out = File(arguments.required("out"))
    val input = File(path)
    val reference = referenceOf(arguments.value("reference"))
    val envelope = arguments.choice("envelope", ENVELOPE_CHOICES, EnvelopeMethod.LOWPASS)
    fun options(name: String, levelReference: LevelReference = LevelReference.FullScale) = try {
        FitOptions(envelope = envelope, levelReference = levelReference, name = name)
    } catch (e: IllegalArgumentException) {
        throw UsageException("--name: ${e.message}")
    }
    val defaultName = input.nameWithoutExtension.take(64).ifBlank { "gesture" }
    if (input.isDirectory) {
        if (reference !is ReferenceChoice.Strongest) throw UsageException("--in: $input is a directory; a batch needs --reference strongest")
        val files = input.listFiles { f -> f.isFile && f.extension.lowercase() in setOf("wav", "csv") }?.sortedBy { it.name }.orEmpty()
        if (files.isEmpty()) throw UsageException("--in: $input holds no .wav or .csv recording")
        val recordings = files.map(::readRecording)
        val fits = try {
            // One set of options for the batch; each icon is then named after its file.
            IconFitter.fitBatch(recordings, arguments.value("channel"), options("gesture")).mapIndexed { i, fit ->
                IconFit(fit.icon.copy(name = files[i].nameWithoutExtension.take(64).ifBlank { "gesture" }), fit.report)
            }
        } catch (e: IllegalArgumentException) {
            throw UsageException("$path: ${e.message}")
        }
        OutputFiles.ensureDirectory(out)
        for ((i, fit) in fits.withIndex()) {
            OutputFiles.write(File(out, files[i].nameWithoutExtension + ".json")) { it.write((IconJson.encode(fit.icon, "  ") + "\n").toByteArray(Charsets.UTF_8)) }
            if (arguments.flag("json")) console.out.println(SchemaJson.encodeElement(fitJson(fit), "  ")) else console.out.print("${files[i].name}: " + describeFit(fit))
        }
        return
    }
    val recording = readRecording(input)
    val fit = try {
        when (reference) {
            is ReferenceChoice.Fixed -> IconFitter.fit(recording, arguments.value("channel"), options(arguments.value("name") ?: defaultName, reference.reference))
            // A single recording is a batch of one: its own gesture is the strongest.
            is ReferenceChoice.Strongest -> IconFitter.fitBatch(listOf(recording), arguments.value("channel"), options(arguments.value("name") ?: defaultName)).single()
        }
    } catch (e: IllegalArgumentException) {
        throw UsageException("$path: ${e.message}")
    }
    OutputFiles.write(out) { it.write((IconJson.encode(fit.icon, "  ") + "\n").toByteArray(Charsets.UTF_8)) }
    if (arguments.flag("json")) console.out.println(SchemaJson.encodeElement(fitJson(fit), "  ")) else console.out.print(describeFit(fit))
}

/** `hapticon fit-bench [--trials N] [--seed S]`: the synthetic parameter-recovery table. */
fun runFitBench(args: List<String>, console: Console) {
    val arguments = Arguments.parse("fit-bench", args, valueOptions = setOf("trials", "seed"))
    arguments.requireNoPositionals()
    val trials = arguments.int("trials", 20)
    if (trials !in 1..10_000) throw UsageException("--trials must be in 1..10000, got $trials")
    val seedText = arguments.value("seed") ?: "1"
    val seed = seedText.toLongOrNull() ?: throw UsageException("--seed must be a whole number, got '$seedText'")
    console.out.println("fit-bench: $trials random icons per row, seed $seed, 44.1 kHz, white Gaussian noise; mean |error|")
    console.out.print(FitBenchmark.format(FitBenchmark.run(trials, seed)))
}

/** Reads a `.wav` or `.csv` recording; every problem becomes a one-line [UsageException]. */
private fun readRecording(file: File): Recording {
    if (file.isDirectory) throw UsageException("--in: $file is a directory, not a file")
    if (!file.isFile) throw UsageException("--in: no such file: $file")
    return try {
        when (file.extension.lowercase()) {
            "wav" -> file.inputStream().buffered().use { RecordingWav.read(it, file.path) }
            "csv" -> RecordingCsv.read(file.readText(Charsets.UTF_8), file.path)
            else -> throw UsageException("--in: $file must be a .wav or .csv recording")
        }
    } catch (e: RecordingFormatException) {
        throw UsageException(e.message.orEmpty())
    } catch (e: IOException) {
        throw UsageException("cannot read $file: ${e.message}")
    }
}

/** The human-readable fit: icon line, then one line per parameter and the report figures. */
internal fun describeFit(fit: IconFit): String {
    val r = fit.report
    val icon = fit.icon
    val out = StringBuilder()
    out.append(String.format(Locale.ROOT, "icon %s: attack %.4f s, sustain %.4f s, level %.3f, release %.4f s, note %.0f, period %.4f s, count %d%n",
        icon.name, icon.attack, icon.sustain, icon.level, icon.release, icon.note, icon.period, icon.count))
    out.append(String.format(Locale.ROOT, "channel %s at %.1f Hz: %s, dominant %.2f Hz%n", r.channel, r.sampleRate, r.kind.name.lowercase(), r.dominantFrequencyHz))
    out.append("envelope: ${r.envelopeMethod.name.lowercase()}, ${r.envelopeSetting}\n")
    out.append("level reference: ${r.levelReference}\n")
    for (p in r.parameters) {
        out.append(String.format(Locale.ROOT, "  %-8s %10.4f%s  %s%n", p.name, p.value, if (p.clamped) String.format(Locale.ROOT, " (measured %.4f)", p.measured) else "", p.how))
    }
    out.append(String.format(Locale.ROOT, "fit: RMS error %.4f of peak, R² %.4f; SNR %s%n", r.fitRmsError, r.rSquared,
        r.snrDb?.let { String.format(Locale.ROOT, "%.1f dB", it) } ?: "not measurable (no quiet part)"))
    out.append("onsets (s): ${r.onsets.joinToString(" ") { String.format(Locale.ROOT, "%.4f", it) }}\n")
    for (w in r.warnings) out.append("warning: $w\n")
    return out.toString()
}

/** The fit as one JSON object: the icon (IconJson) and the report. */
internal fun fitJson(fit: IconFit): JsonObject {
    val r = fit.report
    val report = linkedMapOf<String, JsonElement>(
        "channel" to JsonPrimitive(r.channel),
        "sample_rate" to shortNumber(r.sampleRate),
        "kind" to JsonPrimitive(r.kind.name.lowercase()),
        "dominant_frequency_hz" to shortNumber(r.dominantFrequencyHz),
        "envelope" to JsonPrimitive(r.envelopeMethod.name.lowercase()),
        "envelope_setting" to JsonPrimitive(r.envelopeSetting),
        "envelope_peak" to shortNumber(r.envelopePeak),
        "level_reference" to JsonPrimitive(r.levelReference),
        "level_reference_value" to shortNumber(r.levelReferenceValue),
        "parameters" to JsonArray(r.parameters.map {
            JsonObject(linkedMapOf("name" to JsonPrimitive(it.name), "value" to shortNumber(it.value), "measured" to shortNumber(it.measured), "how" to JsonPrimitive(it.how)))
        }),
        "onsets_s" to JsonArray(r.onsets.map { shortNumber(it) }),
        "fit_rms_error" to shortNumber(r.fitRmsError),
        "r_squared" to shortNumber(r.rSquared),
        "snr_db" to (r.snrDb?.let { shortNumber(it) } ?: JsonNull),
        "warnings" to JsonArray(r.warnings.map { JsonPrimitive(it) }),
    )
    return JsonObject(linkedMapOf("icon" to IconJson.toJsonElement(fit.icon), "report" to JsonObject(report)))
}
