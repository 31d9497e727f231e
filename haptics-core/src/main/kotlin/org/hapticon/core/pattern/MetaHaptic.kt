package org.hapticon.core.pattern

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.io.HapticFormats
import org.hapticon.core.io.SchemaJson
import org.hapticon.core.io.shortNumber
import java.util.Locale
import kotlin.math.abs
import kotlin.math.sqrt

/**
 * Meta Haptics Studio / Lofelt `.haptic` files, data model v1 (Lofelt/NiceVibrations
 * `core/datamodel/src/v1.rs`): `version` {major, minor, patch}, optional `metadata`, and
 * `signals.continuous.envelopes` with `amplitude` breakpoints {time, amplitude, emphasis?: {amplitude,
 * frequency}} and optional `frequency` breakpoints {time, frequency}, every value normalised 0..1.
 *
 * Reading follows Meta's validator (facebook/meta-haptics-sdk `core/haptic_data/src/v1.rs`, `HapticData::validate`)
 * in the `LegacyCompatibility` mode its loaders use (`haptic_data_from_json`), naming the file's member:
 * - refused: an empty or single-breakpoint amplitude envelope, a zero duration, breakpoint times that go back,
 *   values outside [0, 1], an emphasis weaker than its breakpoint;
 * - `version.minor` and `version.patch` are optional (0 when absent: `#[serde(default)]` in `version.rs`), as is
 *   `metadata`;
 * - a frequency breakpoint outside the amplitude envelope's time span is refused only by Meta's `Strict` mode,
 *   "to stay compatible with .haptic files that were created with earlier versions of Haptics Studio": Lofelt
 *   Studio's exports end their frequency envelope up to a few ms after the amplitude envelope. Such an envelope is
 *   clipped to the amplitude envelope's span (the value at each edge interpolated in the file's normalised
 *   frequency, which is what `.haptic` interpolates), with one note; nothing plays there, as a clip ends with its
 *   last amplitude breakpoint (`HapticData::duration`).
 * Amplitude is the pattern's amplitude; a normalised frequency becomes Hz through [FrequencyMapping]; an
 * emphasis becomes a [Transient] with intensity √(emphasis amplitude) and sharpness = emphasis frequency, as
 * Meta's AHAP converter maps them (`core/datamodel/src/ios/v1.rs`). Without a frequency envelope the carrier
 * sits at the middle of the range (noted).
 *
 * Writing puts every transient on an amplitude breakpoint (one is inserted at the curve's value if none is at
 * that time) as its emphasis, and clips the frequency envelope to the amplitude envelope's span, noting
 * anything it had to change.
 */
public object MetaHaptic {
    /** The data-model major version this build reads and writes. */
    public const val MAJOR_VERSION: Int = HapticFormats.HAPTIC_MAJOR_VERSION

    /**
     * The pattern in `.haptic` [bytes], named [name]. Throws [PatternException] naming the member
     * (`signals.continuous.envelopes.amplitude: needs at least two breakpoints`) or
     * [org.hapticon.core.io.JsonException] for malformed JSON.
     */
    public fun read(bytes: ByteArray, name: String, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): PatternImport {
        val root = SchemaJson.parseUtf8(bytes).asObject("haptic")
        val version = root["version"].asObject("version")
        val major = version["major"].asNumber("version.major")
        version["minor"]?.asNumber("version.minor")
        version["patch"]?.asNumber("version.patch")
        if (major != MAJOR_VERSION.toDouble()) fail("version.major", "unsupported data model version $major (this build reads $MAJOR_VERSION)")
        val envelopesPath = "signals.continuous.envelopes"
        val envelopes = root["signals"].asObject("signals")["continuous"].asObject("signals.continuous")["envelopes"].asObject(envelopesPath)
        val amplitudePath = "$envelopesPath.amplitude"
        val breakpoints = envelopes["amplitude"].asArray(amplitudePath).objects(amplitudePath)
        if (breakpoints.isEmpty()) fail(amplitudePath, "is empty; it needs at least two breakpoints")
        if (breakpoints.size == 1) fail(amplitudePath, "has a single breakpoint; it needs at least two")
        val notes = ArrayList<String>()
        val keys = ArrayList<AmplitudeKey>()
        val taps = ArrayList<Transient>()
        for ((path, bp) in breakpoints) {
            val time = bp["time"].asTime("$path.time")
            val amplitude = bp["amplitude"].asUnit("$path.amplitude")
            if (keys.isNotEmpty() && time < keys.last().time) fail("$path.time", "must not be before the previous breakpoint (${keys.last().time} s), was $time")
            keys += AmplitudeKey(time, amplitude)
            bp["emphasis"]?.let { e ->
                val emphasis = e.asObject("$path.emphasis")
                val strength = emphasis["amplitude"].asUnit("$path.emphasis.amplitude")
                val frequency = emphasis["frequency"].asUnit("$path.emphasis.frequency")
                if (strength < amplitude) fail("$path.emphasis.amplitude", "must not be below the breakpoint's amplitude $amplitude, was $strength")
                taps += Transient(time, sqrt(strength), frequency)
            }
        }
        val first = keys.first().time
        val last = keys.last().time
        if (last <= first) fail(amplitudePath, "has zero duration (every breakpoint at $first s)")
        val frequencyPath = "$envelopesPath.frequency"
        val frequency = when (val f = envelopes["frequency"]) {
            null, is kotlinx.serialization.json.JsonNull -> {
                notes += "no frequency envelope: the carrier stays at ${hz(mapping.hertzOf(0.5))}, the middle of the range"
                listOf(FrequencyKey(0.0, mapping.hertzOf(0.5)))
            }
            else -> {
                val normalised = f.asArray(frequencyPath).objects(frequencyPath).map { (path, bp) ->
                    bp["time"].asTime("$path.time") to bp["frequency"].asUnit("$path.frequency")
                }
                for (i in 1 until normalised.size) {
                    if (normalised[i].first < normalised[i - 1].first) fail("$frequencyPath[$i].time", "must not be before the previous breakpoint")
                }
                if (normalised.isEmpty()) {
                    notes += "empty frequency envelope: the carrier stays at the middle of the range"
                    listOf(FrequencyKey(0.0, mapping.hertzOf(0.5)))
                } else {
                    clipToSpan(normalised, first, last, notes).map { (t, x) -> FrequencyKey(t, mapping.hertzOf(x)) }
                }
            }
        }
        return PatternImport(HapticPattern(name, keys, frequency, taps), notes)
    }

    /** [pattern] as `.haptic` text, with notes on what the format could not keep. */
    public fun write(pattern: HapticPattern, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): PatternExport {
        val notes = ArrayList<String>()
        val keys = ArrayList<AmplitudeKey>(pattern.amplitude)
        // The format needs two breakpoints spanning a positive duration, and every emphasis on a breakpoint.
        val end = maxOf(pattern.duration, keys.lastOrNull()?.time ?: 0.0)
        if (keys.isEmpty() || keys.last().time < end) {
            if (keys.isNotEmpty() && keys.last().amplitude != 0.0) keys += AmplitudeKey(keys.last().time, 0.0)
            if (keys.isEmpty()) keys += AmplitudeKey(0.0, 0.0)
            keys += AmplitudeKey(end, 0.0)
        }
        fun indexAt(t: Double) = keys.indexOfFirst { abs(it.time - t) < 1e-9 }
        // First a breakpoint at every transient's time (on the curve), then the emphasis on it.
        for (tap in pattern.transients) {
            if (indexAt(tap.time) >= 0) continue
            val at = keys.indexOfFirst { it.time > tap.time }.let { if (it < 0) keys.size else it }
            keys.add(at, AmplitudeKey(tap.time, pattern.amplitudeAt(tap.time)))
        }
        val emphasis = HashMap<Int, Transient>()
        for (tap in pattern.transients) {
            val index = indexAt(tap.time)
            val earlier = emphasis[index]
            if (earlier != null) {
                notes += "two transients at ${seconds(tap.time)}: the stronger one kept"
                if (earlier.intensity >= tap.intensity) continue
            }
            emphasis[index] = tap
        }
        val amplitude = keys.mapIndexed { i, key ->
            val members = linkedMapOf<String, JsonElement>("time" to shortNumber(key.time), "amplitude" to shortNumber(key.amplitude))
            emphasis[i]?.let { tap ->
                var strength = tap.intensity * tap.intensity
                if (strength < key.amplitude) {
                    notes += "transient at ${seconds(tap.time)} raised to the breakpoint's amplitude ${"%.3f".format(Locale.ROOT, key.amplitude)}: an emphasis cannot be weaker"
                    strength = key.amplitude
                }
                members["emphasis"] = JsonObject(linkedMapOf("amplitude" to shortNumber(strength), "frequency" to shortNumber(tap.sharpness)))
            }
            JsonObject(members)
        }
        val span = keys.first().time..keys.last().time
        val inside = pattern.frequency.filter { it.time in span }
        if (inside.size < pattern.frequency.size) notes += "${pattern.frequency.size - inside.size} frequency keys outside the amplitude envelope dropped"
        val withStart = listOf(FrequencyKey(span.start, pattern.frequencyAt(span.start))).filter { inside.firstOrNull()?.time != span.start } + inside
        // `.haptic` interpolates the normalised frequency, which is logarithmic in Hz: add points where that strays.
        val frequency = densify(withStart.map { it.time to it.hertz.coerceIn(mapping.minHz, mapping.maxHz) }, mapping::normalizedOf, mapping::hertzOf) { it * 0.004 }
            .map { (t, x) -> JsonObject(linkedMapOf("time" to shortNumber(t), "frequency" to shortNumber(x))) }
        val outside = pattern.frequency.count { it.hertz !in mapping }
        if (outside > 0) notes += "$outside frequency keys outside ${hz(mapping.minHz)}..${hz(mapping.maxHz)} clamped to the range"
        val root = JsonObject(linkedMapOf(
            "version" to JsonObject(linkedMapOf("major" to shortNumber(MAJOR_VERSION.toDouble()), "minor" to shortNumber(0.0), "patch" to shortNumber(0.0))),
            "metadata" to JsonObject(linkedMapOf("editor" to JsonPrimitive("Hapticon"), "description" to JsonPrimitive(pattern.name))),
            "signals" to JsonObject(linkedMapOf("continuous" to JsonObject(linkedMapOf("envelopes" to JsonObject(linkedMapOf(
                "amplitude" to JsonArray(amplitude),
                "frequency" to JsonArray(frequency),
            )))))),
        ))
        return PatternExport(SchemaJson.encodeElement(root, "  ") + "\n", notes)
    }

    /**
     * [points] (time, normalised frequency, in time order) within first..last: the points inside, and where points
     * lie outside, the value at that edge (interpolated, or held from the nearest point) in their place; one note.
     */
    private fun clipToSpan(points: List<Pair<Double, Double>>, first: Double, last: Double, notes: MutableList<String>): List<Pair<Double, Double>> {
        val before = points.count { it.first < first }
        val after = points.count { it.first > last }
        if (before == 0 && after == 0) return points
        fun valueAt(t: Double): Double {
            val next = points.indexOfFirst { it.first >= t }
            if (next <= 0) return if (next == 0) points[0].second else points.last().second
            val (t0, x0) = points[next - 1]
            val (t1, x1) = points[next]
            return if (t1 == t0) x1 else x0 + (x1 - x0) * (t - t0) / (t1 - t0)
        }
        val clipped = ArrayList<Pair<Double, Double>>()
        points.filterTo(clipped) { it.first in first..last }
        if (before > 0 && clipped.firstOrNull()?.first != first) clipped.add(0, first to valueAt(first))
        if (after > 0 && clipped.lastOrNull()?.first != last) clipped += last to valueAt(last)
        val what = listOfNotNull(
            if (before > 0) "$before before its start (up to ${millis(first - points.first().first)})" else null,
            if (after > 0) "$after past its end (up to ${millis(points.last().first - last)})" else null,
        ).joinToString(" and ")
        notes += "frequency envelope clipped to the amplitude envelope (${seconds(first)}..${seconds(last)}): $what breakpoint(s) outside it, as Lofelt Studio exports write"
        return clipped
    }

    private fun millis(seconds: Double): String = String.format(Locale.ROOT, "%.2f ms", seconds * 1000.0)

}
