package org.hapticon.core.pattern

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.EnvelopeShape
import kotlin.math.abs

/**
 * This icon as a pattern: a constant carrier at the icon's note and an amplitude curve with the corners of every
 * repetition's envelope, in continuous time. The corners, their values and how repetitions combine are the icon's
 * [EnvelopeShape] under [model], the definition the renderers sample:
 *
 * - [EnvelopeModel.PROCESSING] (the default, what the study's participants felt): Processing Sound's
 *   `Env.play` envelope — attack from 0 to full amplitude, a straight decay to `level` across the sustain time,
 *   release to 0 (processing-sound `Env.java`, "gradual decay towards sustain level across entire sustain
 *   period") — with overlapping repetitions **added**, as JSyn sums every envelope reader connected to the
 *   oscillator's amplitude port (docs/envelope-models.md). A sum above 1 is capped at 1.
 * - [EnvelopeModel.PAPER]: the paper's trapezoid (attack to `level`, flat sustain, release), the louder
 *   repetition winning where they overlap (the crossing points become corners).
 *
 * The curve is exact in continuous time: between consecutive corners every repetition is a straight line.
 * Sample-level rules of the Processing model (phase carry, one-sample minimum, float parameters) belong to the
 * PCM renderer ([org.hapticon.core.render.IconRenderer]), not to the pattern.
 */
public fun HapticIcon.toPattern(model: EnvelopeModel = EnvelopeModel.DEFAULT): HapticPattern {
    val shape = EnvelopeShape.of(this, model)
    val starts = DoubleArray(count) { it * period }
    val corners = sortedSetOf<Double>()
    for (start in starts) corners += shape.corners(start).asList()
    val times = corners.toDoubleArray()
    val combine: (DoubleArray) -> Double = if (shape.sums) { values -> values.sum() } else { values -> values.max() }
    val keys = ArrayList<AmplitudeKey>(2 * times.size)
    for (i in times.indices) {
        val t = times[i]
        // A zero-length attack or release is a step: the value just before and just after the corner differ.
        val before = combine(DoubleArray(count) { shape.valueBefore(t, starts[it]) })
        val after = combine(DoubleArray(count) { shape.valueAfter(t, starts[it]) })
        // (Rounding in the corner arithmetic leaves ~1e-16 differences that are not steps.)
        if (i > 0 && abs(before - after) > 1e-9) keys += AmplitudeKey(t, minOf(1.0, before))
        keys += AmplitudeKey(t, minOf(1.0, after))
        if (!shape.sums && i < times.lastIndex) {
            // Between corners every repetition is a straight line; the louder of two swaps where they cross.
            val next = times[i + 1]
            val from = DoubleArray(count) { shape.valueAfter(t, starts[it]) }
            val to = DoubleArray(count) { shape.valueBefore(next, starts[it]) }
            for (crossing in crossingsOfMax(t, next, from, to)) {
                keys += AmplitudeKey(crossing, minOf(1.0, lineMax(crossing, t, next, from, to)))
            }
        }
    }
    return HapticPattern(name, dropCollinear(keys), listOf(FrequencyKey(0.0, frequency)))
}

private fun lineAt(k: Int, t: Double, a: Double, b: Double, from: DoubleArray, to: DoubleArray): Double =
    from[k] + (to[k] - from[k]) * (t - a) / (b - a)

private fun lineMax(t: Double, a: Double, b: Double, from: DoubleArray, to: DoubleArray): Double =
    from.indices.maxOf { lineAt(it, t, a, b, from, to) }

// The max of straight lines is convex, so its corners inside (a, b) are found by splitting at the crossing of
// the lines that lead at each end until one line leads at both.
private fun crossingsOfMax(a: Double, b: Double, from: DoubleArray, to: DoubleArray): List<Double> {
    val out = ArrayList<Double>()
    fun search(lo: Double, hi: Double, depth: Int) {
        if (depth > 64 || hi - lo < 1e-12) return
        // On a tie the steeper line leads just after lo, the shallower one just before hi.
        val atLo = from.indices.maxWith(compareBy({ lineAt(it, lo, a, b, from, to) }, { to[it] - from[it] }))
        val atHi = from.indices.maxWith(compareBy({ lineAt(it, hi, a, b, from, to) }, { from[it] - to[it] }))
        if (atLo == atHi) return
        val gapLo = lineAt(atLo, lo, a, b, from, to) - lineAt(atHi, lo, a, b, from, to)
        val gapHi = lineAt(atLo, hi, a, b, from, to) - lineAt(atHi, hi, a, b, from, to)
        if (gapLo == gapHi) return
        val crossing = lo + (hi - lo) * gapLo / (gapLo - gapHi)
        if (crossing <= lo || crossing >= hi) return
        search(lo, crossing, depth + 1)
        out += crossing
        search(crossing, hi, depth + 1)
    }
    search(a, b, 0)
    return out
}

// Removes corners that lie on the straight line through their neighbours (a sum of flat parts, say).
private fun dropCollinear(keys: List<AmplitudeKey>): List<AmplitudeKey> {
    if (keys.size < 3) return keys
    val out = ArrayList<AmplitudeKey>(keys.size)
    out += keys[0]
    for (i in 1 until keys.lastIndex) {
        val a = out.last()
        val b = keys[i]
        val c = keys[i + 1]
        val inside = a.time < b.time && b.time < c.time
        val onLine = inside &&
            abs(a.amplitude + (c.amplitude - a.amplitude) * (b.time - a.time) / (c.time - a.time) - b.amplitude) < 1e-12
        if (!onLine) out += b
    }
    out += keys.last()
    return out
}
