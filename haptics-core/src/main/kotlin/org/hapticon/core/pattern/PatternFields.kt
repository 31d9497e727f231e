package org.hapticon.core.pattern

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.doubleOrNull
import org.hapticon.core.io.snippet
import java.util.Locale

// Typed member access for the loose foreign formats (AHAP, Meta .haptic) over kotlinx trees, failing with a
// PatternException that names the member's path. Hapticon's own pattern document is a @Serializable type (PatternJson).

internal fun fail(path: String, message: String): Nothing = throw PatternException(path, message)

internal fun JsonElement?.asObject(path: String): JsonObject = this as? JsonObject
    ?: fail(path, if (this == null) "missing" else "expected an object, got ${snippet(this)}")

internal fun JsonElement?.asArray(path: String): JsonArray = this as? JsonArray
    ?: fail(path, if (this == null) "missing" else "expected an array, got ${snippet(this)}")

internal fun JsonElement?.asNumber(path: String): Double {
    val number = (this as? JsonPrimitive)?.takeUnless { it.isString || it is JsonNull }?.doubleOrNull
        ?: fail(path, if (this == null) "missing" else "expected a number, got ${snippet(this)}")
    if (!number.isFinite()) fail(path, "must be finite")
    return number
}

internal fun JsonElement?.asString(path: String): String = (this as? JsonPrimitive)?.takeIf { it.isString }?.content
    ?: fail(path, if (this == null) "missing" else "expected a string, got ${snippet(this)}")

internal fun JsonElement?.asTime(path: String): Double {
    val t = asNumber(path)
    if (t < 0.0) fail(path, "must be >= 0 seconds, was $t")
    return t
}

internal fun JsonElement?.asUnit(path: String): Double {
    val x = asNumber(path)
    if (x !in 0.0..1.0) fail(path, "must be in [0, 1], was $x")
    return x
}

internal fun JsonArray.objects(path: String): List<Pair<String, JsonObject>> =
    mapIndexed { i, e -> "$path[$i]".let { it to e.asObject(it) } }

internal fun seconds(t: Double): String = String.format(Locale.ROOT, "%.3f s", t)

internal fun hz(x: Double): String = String.format(Locale.ROOT, "%.1f Hz", x)

/**
 * [points] (time, value) mapped through [forward] into another format's scale, with points added between them
 * until straight lines in that scale, mapped [back], stay within [tolerance] of the straight lines in ours.
 * Needed because formats interpolate different quantities: AHAP interpolates intensity (√amplitude) and
 * sharpness, `.haptic` a normalised frequency, Hapticon amplitude and Hz.
 */
internal fun densify(
    points: List<Pair<Double, Double>>,
    forward: (Double) -> Double,
    back: (Double) -> Double,
    tolerance: (Double) -> Double,
): List<Pair<Double, Double>> {
    val out = ArrayList<Pair<Double, Double>>(points.size)
    fun split(t0: Double, v0: Double, t1: Double, v1: Double, depth: Int) {
        val tm = 0.5 * (t0 + t1)
        val vm = 0.5 * (v0 + v1)
        val theirs = back(0.5 * (forward(v0) + forward(v1)))
        if (depth >= 10 || t1 - t0 < 1e-5 || kotlin.math.abs(theirs - vm) <= tolerance(vm)) return
        split(t0, v0, tm, vm, depth + 1)
        out += tm to forward(vm)
        split(tm, vm, t1, v1, depth + 1)
    }
    for (i in points.indices) {
        val (t, v) = points[i]
        if (i > 0) {
            val (tp, vp) = points[i - 1]
            if (t > tp) split(tp, vp, t, v, 0)
        }
        out += t to forward(v)
    }
    return out
}
