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
import kotlin.math.ceil
import kotlin.math.sqrt

/**
 * Apple Core Haptics AHAP files (Apple, "Representing haptic patterns in AHAP files").
 *
 * Reading flattens the pattern's events into one [HapticPattern]:
 * - `HapticContinuous` (`Time`, `EventDuration`, `HapticIntensity` I, `HapticSharpness` S, `AttackTime` and
 *   `ReleaseTime` as linear ramps of the intensity inside the event) and `HapticTransient` (→ [Transient]).
 *   A missing intensity reads as 1 and a missing sharpness as 0.5 (our assumption; the file format leaves
 *   them to the engine's defaults); `DecayTime` and `Sustained` are not modelled and noted when given.
 * - Dynamic parameters (`Parameter`, a step at its `Time`) and `ParameterCurve`s (control points relative to
 *   the curve's `Time`, linear between them, held after the last) for `HapticIntensityControl`, which
 *   multiplies intensity (0..1), and `HapticSharpnessControl`, which adds to sharpness (−1..1), as Apple's
 *   `CHHapticDynamicParameter.value` documentation states. A later curve of the same parameter takes over at
 *   its start. Other dynamic parameters and the audio events are dropped with a note. The controls shape the
 *   continuous events only; a transient keeps its own intensity and sharpness, as Meta's converter assumes when
 *   it writes transients beside intensity curves without compensating for them.
 * - Intensity becomes amplitude as amplitude = intensity², sharpness becomes frequency through
 *   [FrequencyMapping] (normalised = sharpness²): the inverse of Meta's converter
 *   (Lofelt/NiceVibrations `core/datamodel/src/ios/v1.rs`). Overlapping continuous events add (capped at 1,
 *   noted) and the most intense one sets the carrier.
 * - The product of the curves is not piecewise linear, so the amplitude curve gets a key at every event edge
 *   and control point and is subdivided until straight lines stay within 0.002 of it.
 * - `Version` is optional. Apple's own sample files have commas before closing brackets; they are accepted.
 *
 * Writing follows Meta's converter (facebook/meta-haptics-sdk `core/haptic_data/src/ahap.rs`): `HapticContinuous`
 * events of intensity 1 and sharpness 0, one per 30 s (the longest Core Haptics plays), shaped by `HapticIntensityControl` and `HapticSharpnessControl` curves of at most 16
 * control points each (a new curve starts at the previous one's last point), plus one `HapticTransient` per
 * transient.
 */
public object Ahap {
    /** Most control points in one `ParameterCurve` (the limit Meta's converter writes to). */
    public const val MAX_CURVE_POINTS: Int = 16

    /** Longest `HapticContinuous` event Core Haptics plays. */
    public const val MAX_CONTINUOUS_SECONDS: Double = 30.0

    /**
     * The pattern in AHAP [bytes], named [name]. Throws [PatternException] naming the member
     * (`Pattern[3].Event.EventDuration: missing`) or [org.hapticon.core.io.JsonException] for malformed JSON.
     */
    public fun read(bytes: ByteArray, name: String, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): PatternImport {
        val root = SchemaJson.parseUtf8(bytes, allowTrailingCommas = true).asObject("AHAP")
        root["Version"]?.asNumber("Version")
        val notes = ArrayList<String>()
        val continuous = ArrayList<ContinuousEvent>()
        val taps = ArrayList<Pair<Double, Pair<Double, Double>>>()
        val controls = mapOf(INTENSITY_CONTROL to ArrayList<ControlCurve>(), SHARPNESS_CONTROL to ArrayList())
        for ((path, entry) in root["Pattern"].asArray("Pattern").objects("Pattern")) {
            val kinds = entry.keys.filter { it in ENTRY_KINDS }
            if (kinds.size != 1) fail(path, "expected exactly one of Event, Parameter, ParameterCurve; got ${entry.keys}")
            val kind = kinds.single()
            val body = entry[kind].asObject("$path.$kind")
            val at = "$path.$kind"
            when (kind) {
                "Event" -> readEvent(body, at, continuous, taps, notes)
                "Parameter" -> {
                    val id = body["ParameterID"].asString("$at.ParameterID")
                    val time = body["Time"].asTime("$at.Time")
                    val value = body["ParameterValue"].asNumber("$at.ParameterValue")
                    controls[id]?.add(ControlCurve(time, listOf(time to checkControl(id, value, "$at.ParameterValue"))))
                        ?: notes.add("dynamic parameter $id at ${seconds(time)} dropped: not modelled")
                }
                "ParameterCurve" -> {
                    val id = body["ParameterID"].asString("$at.ParameterID")
                    val time = body["Time"].asTime("$at.Time")
                    val points = body["ParameterCurveControlPoints"].asArray("$at.ParameterCurveControlPoints")
                        .objects("$at.ParameterCurveControlPoints").map { (p, point) ->
                            (time + point["Time"].asTime("$p.Time")) to checkControl(id, point["ParameterValue"].asNumber("$p.ParameterValue"), "$p.ParameterValue")
                        }
                    if (points.isEmpty()) fail("$at.ParameterCurveControlPoints", "needs at least one control point")
                    for (i in 1 until points.size) {
                        if (points[i].first < points[i - 1].first) fail("$at.ParameterCurveControlPoints[$i].Time", "must not be before the previous point")
                    }
                    controls[id]?.add(ControlCurve(time, points))
                        ?: notes.add("parameter curve $id at ${seconds(time)} dropped: not modelled")
                }
            }
        }
        val scene = Scene(continuous, controls.getValue(INTENSITY_CONTROL).sortedBy { it.start }, controls.getValue(SHARPNESS_CONTROL).sortedBy { it.start }, mapping)
        val pattern = HapticPattern(
            name,
            scene.amplitudeKeys(notes),
            scene.frequencyKeys(),
            taps.sortedBy { it.first }.map { (time, params) -> Transient(time, params.first, params.second) },
        )
        return PatternImport(pattern, notes)
    }

    /** [pattern] as AHAP text, with notes on what the format could not keep (frequencies outside [mapping]). */
    public fun write(pattern: HapticPattern, mapping: FrequencyMapping = FrequencyMapping.DEFAULT): PatternExport {
        val notes = ArrayList<String>()
        val entries = ArrayList<JsonElement>()
        if (pattern.amplitude.isNotEmpty()) {
            val start = pattern.amplitude.first().time
            val end = pattern.continuousDuration
            // Core Haptics plays a continuous event for at most 30 s, so a longer pattern takes consecutive events,
            // as Meta's converter writes them (`ahap_continuous_events_from_breakpoints`); the curves span them all.
            val events = maxOf(1, ceil((end - start) / MAX_CONTINUOUS_SECONDS).toInt())
            for (k in 0 until events) {
                val time = start + k * MAX_CONTINUOUS_SECONDS
                entries += entry("Event", "Time" to num(time), "EventType" to JsonPrimitive("HapticContinuous"),
                    "EventDuration" to num(minOf(MAX_CONTINUOUS_SECONDS, end - time)),
                    "EventParameters" to params("HapticIntensity" to 1.0, "HapticSharpness" to 0.0))
            }
            entries += curves(INTENSITY_CONTROL, densify(pattern.amplitude.map { it.time to it.amplitude }, ::sqrt, { it * it }, { AMPLITUDE_TOLERANCE }))
            val outside = pattern.frequency.count { it.hertz !in mapping }
            if (outside > 0) notes += "$outside frequency keys outside ${hz(mapping.minHz)}..${hz(mapping.maxHz)} clamped to the range"
            val frequency = pattern.frequency.map { maxOf(start, it.time) to it.hertz.coerceIn(mapping.minHz, mapping.maxHz) }
            entries += curves(SHARPNESS_CONTROL, densify(frequency, mapping::sharpnessOf, mapping::hertzOfSharpness) { it * FREQUENCY_TOLERANCE })
        }
        for (tap in pattern.transients) {
            entries += entry("Event", "Time" to num(tap.time), "EventType" to JsonPrimitive("HapticTransient"),
                "EventParameters" to params("HapticIntensity" to tap.intensity, "HapticSharpness" to tap.sharpness))
        }
        val root = JsonObject(linkedMapOf(
            "Version" to num(HapticFormats.AHAP_VERSION.toDouble()),
            "Metadata" to JsonObject(linkedMapOf("Project" to JsonPrimitive(pattern.name), "Created" to JsonPrimitive("Hapticon"))),
            "Pattern" to JsonArray(entries),
        ))
        return PatternExport(SchemaJson.encodeElement(root, "  ") + "\n", notes)
    }

    private fun readEvent(
        body: JsonObject,
        at: String,
        continuous: MutableList<ContinuousEvent>,
        taps: MutableList<Pair<Double, Pair<Double, Double>>>,
        notes: MutableList<String>,
    ) {
        val time = body["Time"].asTime("$at.Time")
        val type = body["EventType"].asString("$at.EventType")
        val params = HashMap<String, Double>()
        (body["EventParameters"] ?: JsonArray(emptyList())).asArray("$at.EventParameters").objects("$at.EventParameters").forEach { (p, param) ->
            params[param["ParameterID"].asString("$p.ParameterID")] = param["ParameterValue"].asNumber("$p.ParameterValue")
        }
        val intensity = params["HapticIntensity"] ?: 1.0
        val sharpness = params["HapticSharpness"] ?: 0.5
        if (intensity !in 0.0..1.0) fail("$at.EventParameters", "HapticIntensity must be in [0, 1], was $intensity")
        if (sharpness !in 0.0..1.0) fail("$at.EventParameters", "HapticSharpness must be in [0, 1], was $sharpness")
        when (type) {
            "HapticTransient" -> taps += time to (intensity to sharpness)
            "HapticContinuous" -> {
                val duration = body["EventDuration"].asTime("$at.EventDuration")
                if (duration > MAX_CONTINUOUS_SECONDS) fail("$at.EventDuration", "must be at most $MAX_CONTINUOUS_SECONDS s, was $duration")
                if (duration == 0.0) {
                    notes += "continuous event at ${seconds(time)} has no duration and was dropped"
                    return
                }
                if ((params["DecayTime"] ?: 0.0) != 0.0) notes += "DecayTime of the event at ${seconds(time)} ignored: not modelled"
                if (params["Sustained"] == 0.0) notes += "Sustained = 0 of the event at ${seconds(time)} ignored: played sustained"
                continuous += ContinuousEvent(time, duration, intensity, sharpness, maxOf(0.0, params["AttackTime"] ?: 0.0), maxOf(0.0, params["ReleaseTime"] ?: 0.0))
            }
            "AudioContinuous", "AudioCustom" -> notes += "$type event at ${seconds(time)} dropped: Hapticon plays haptics only"
            else -> fail("$at.EventType", "unknown event type \"$type\"")
        }
    }

    private fun checkControl(id: String, value: Double, path: String): Double {
        val range = if (id == SHARPNESS_CONTROL) -1.0..1.0 else 0.0..1.0
        if (id in setOf(INTENSITY_CONTROL, SHARPNESS_CONTROL) && value !in range) fail(path, "$id must be in $range, was $value")
        return value
    }

    // Curves of at most MAX_CURVE_POINTS points; each further curve begins with the previous one's last point.
    private fun curves(id: String, points: List<Pair<Double, Double>>): List<JsonElement> {
        val out = ArrayList<JsonElement>()
        var from = 0
        while (true) {
            val to = minOf(points.size, from + MAX_CURVE_POINTS)
            val chunk = points.subList(from, to)
            val start = chunk.first().first
            out += entry("ParameterCurve", "ParameterID" to JsonPrimitive(id), "Time" to num(start),
                "ParameterCurveControlPoints" to JsonArray(chunk.map { (t, v) -> JsonObject(linkedMapOf("Time" to num(t - start), "ParameterValue" to num(v))) }))
            if (to == points.size) return out
            from = to - 1
        }
    }

    private fun entry(kind: String, vararg members: Pair<String, JsonElement>): JsonElement =
        JsonObject(linkedMapOf(kind to JsonObject(linkedMapOf(*members))))

    private fun params(vararg values: Pair<String, Double>): JsonElement =
        JsonArray(values.map { (id, v) -> JsonObject(linkedMapOf("ParameterID" to JsonPrimitive(id), "ParameterValue" to num(v))) })

    private fun num(x: Double): JsonElement = shortNumber(x)

    // Written curves stay within these of the pattern (absolute amplitude, relative frequency).
    private const val AMPLITUDE_TOLERANCE = 0.004
    private const val FREQUENCY_TOLERANCE = 0.004
    private const val INTENSITY_CONTROL = "HapticIntensityControl"
    private const val SHARPNESS_CONTROL = "HapticSharpnessControl"
    private val ENTRY_KINDS = setOf("Event", "Parameter", "ParameterCurve")
}

private data class ContinuousEvent(
    val start: Double,
    val duration: Double,
    val intensity: Double,
    val sharpness: Double,
    val attack: Double,
    val release: Double,
) {
    val end: Double get() = start + duration

    /** Active at [t]: just after t when [after], else just before t (an event's edges are steps). */
    fun activeAt(t: Double, after: Boolean): Boolean = if (after) t >= start && t < end else t > start && t <= end

    fun rampedIntensity(t: Double): Double {
        var gain = 1.0
        if (attack > 0.0) gain = minOf(gain, (t - start) / attack)
        if (release > 0.0) gain = minOf(gain, (end - t) / release)
        return intensity * gain.coerceIn(0.0, 1.0)
    }
}

/** A dynamic-parameter curve; a single `Parameter` is a curve of one point. Absolute times. */
private data class ControlCurve(val start: Double, val points: List<Pair<Double, Double>>) {
    fun valueAt(t: Double): Double {
        if (t <= points.first().first) return points.first().second
        for (i in 1 until points.size) {
            val (t1, v1) = points[i]
            if (t <= t1) {
                val (t0, v0) = points[i - 1]
                return if (t1 == t0) v1 else v0 + (v1 - v0) * (t - t0) / (t1 - t0)
            }
        }
        return points.last().second
    }
}

private class Scene(
    private val events: List<ContinuousEvent>,
    private val intensityCurves: List<ControlCurve>,
    private val sharpnessCurves: List<ControlCurve>,
    private val mapping: FrequencyMapping,
) {
    private val knots: DoubleArray = buildSet {
        for (e in events) {
            add(e.start); add(e.end)
            if (e.attack > 0.0 && e.attack < e.duration) add(e.start + e.attack)
            if (e.release > 0.0 && e.release < e.duration) add(e.end - e.release)
        }
        for (c in intensityCurves + sharpnessCurves) { add(c.start); c.points.forEach { add(it.first) } }
    }.filter { it <= end() }.sorted().toDoubleArray()

    private fun end(): Double = events.maxOfOrNull { it.end } ?: 0.0

    private fun intensityControl(t: Double, after: Boolean): Double = control(intensityCurves, t, after, default = 1.0)

    private fun sharpnessControl(t: Double, after: Boolean): Double = control(sharpnessCurves, t, after, default = 0.0)

    private fun control(curves: List<ControlCurve>, t: Double, after: Boolean, default: Double): Double {
        val active = curves.lastOrNull { if (after) it.start <= t else it.start < t } ?: return default
        return active.valueAt(t)
    }

    fun amplitude(t: Double, after: Boolean): Double {
        val gain = intensityControl(t, after)
        var sum = 0.0
        for (e in events) {
            if (e.activeAt(t, after)) {
                val i = e.rampedIntensity(t) * gain
                sum += i * i
            }
        }
        return sum
    }

    fun hertz(t: Double, after: Boolean): Double? {
        val loudest = events.filter { it.activeAt(t, after) }.maxByOrNull { it.rampedIntensity(t) } ?: return null
        return mapping.hertzOf(FrequencyMapping.normalizedOfSharpness(loudest.sharpness + sharpnessControl(t, after)))
    }

    fun amplitudeKeys(notes: MutableList<String>): List<AmplitudeKey> {
        if (events.isEmpty()) return emptyList()
        val keys = ArrayList<AmplitudeKey>()
        var clipped = false
        fun add(t: Double, value: Double) {
            if (value > 1.0) clipped = true
            val v = minOf(1.0, value)
            val last = keys.lastOrNull()
            if (last == null || last.time != t || last.amplitude != v) keys += AmplitudeKey(t, v)
        }
        val first = knots.first()
        if (first > 0.0) add(0.0, 0.0)
        for (i in knots.indices) {
            val t = knots[i]
            add(t, amplitude(t, after = false))
            add(t, amplitude(t, after = true))
            if (i < knots.lastIndex) subdivide(t, knots[i + 1], 0, TOLERANCE, ::amplitude, ::add)
        }
        if (clipped) notes += "overlapping continuous events add up past full strength; the sum is capped at 1"
        return keys
    }

    // Adds interior keys where a straight line between a and b strays more than tolerance from the curve.
    private fun subdivide(a: Double, b: Double, depth: Int, tolerance: Double, curve: (Double, Boolean) -> Double, add: (Double, Double) -> Unit) {
        val mid = 0.5 * (a + b)
        val va = curve(a, true)
        val vb = curve(b, false)
        val vm = curve(mid, true)
        if (depth >= 12 || b - a < MIN_SPAN || abs(vm - 0.5 * (va + vb)) <= tolerance) return
        subdivide(a, mid, depth + 1, tolerance, curve, add)
        add(mid, vm)
        subdivide(mid, b, depth + 1, tolerance, curve, add)
    }

    fun frequencyKeys(): List<FrequencyKey> {
        val keys = ArrayList<FrequencyKey>()
        fun add(t: Double, hz: Double) {
            val last = keys.lastOrNull()
            if (last == null || last.time != t || last.hertz != hz) keys += FrequencyKey(t, hz)
        }
        // Hertz is exponential in sharpness², so between knots the curve is subdivided like the amplitude,
        // with the tolerance in semitones' worth of the normalised scale.
        val normalized = { t: Double, after: Boolean -> hertz(t, after)?.let(mapping::normalizedOf) ?: -1.0 }
        for (i in knots.indices) {
            val t = knots[i]
            hertz(t, after = false)?.let { add(t, it) }
            hertz(t, after = true)?.let { add(t, it) }
            if (i < knots.lastIndex && hertz(t, after = true) != null && hertz(knots[i + 1], after = false) != null) {
                subdivide(t, knots[i + 1], 0, FREQUENCY_TOLERANCE, normalized) { at, x -> add(at, mapping.hertzOf(x)) }
            }
        }
        if (keys.isEmpty()) keys += FrequencyKey(0.0, mapping.hertzOf(FrequencyMapping.normalizedOfSharpness(DEFAULT_SHARPNESS)))
        return keys
    }

    private companion object {
        const val TOLERANCE = 0.002
        const val MIN_SPAN = 0.0005
        const val FREQUENCY_TOLERANCE = 0.005
        const val DEFAULT_SHARPNESS = 0.5
    }
}
