package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import java.math.BigDecimal
import java.math.MathContext
import java.math.RoundingMode
import kotlin.math.PI
import kotlin.math.sin

/**
 * Independent reference formulas for the tests, written straight from the icon definition
 * (not by calling the code under test). Phase is computed in BigDecimal so that the reference
 * itself has no drift.
 */
internal object IconReference {
    private val context = MathContext(50)

    /** frac(f · index / fs) in cycles, exact to double precision. */
    fun cycles(frequency: Double, index: Long, sampleRate: Int): Double =
        BigDecimal(frequency).multiply(BigDecimal.valueOf(index))
            .divide(BigDecimal.valueOf(sampleRate.toLong()), context)
            .remainder(BigDecimal.ONE).toDouble()

    /** frac(f · t) in cycles, exact to double precision. */
    fun cyclesAtTime(frequency: Double, t: Double): Double =
        BigDecimal(frequency).multiply(BigDecimal(t)).remainder(BigDecimal.ONE).toDouble()

    /** PAPER: one envelope at local time u seconds. */
    fun paperSingle(icon: HapticIcon, u: Double): Double {
        val a = icon.attack
        val s = icon.sustain
        val r = icon.release
        val l = icon.level
        return when {
            u < 0.0 -> 0.0
            u < a -> l * u / a
            u < a + s -> l
            u < a + s + r -> l * (a + s + r - u) / r
            else -> 0.0
        }
    }

    /** PROCESSING: one envelope at local sample n, boundaries at rounded cumulative times. */
    fun processingSingle(icon: HapticIcon, n: Long, sampleRate: Int): Double {
        val fs = sampleRate.toDouble()
        val a = icon.attack
        val s = icon.sustain
        val r = icon.release
        val l = icon.level
        val b1 = Math.round(a * fs)
        val b2 = Math.round((a + s) * fs)
        val b3 = Math.round((a + s + r) * fs)
        return when {
            n < 0 -> 0.0
            n < b1 -> 0.0 + (1.0 - 0.0) * n / (a * fs)
            n < b2 -> 1.0 + (l - 1.0) * (n - b1) / (s * fs)
            n < b3 -> l + (0.0 - l) * (n - b2) / (r * fs)
            else -> 0.0
        }
    }

    /** Repetition k starts on the sample nearest to k · period (the documented rendering rule). */
    fun onset(icon: HapticIcon, k: Int, sampleRate: Int): Long = Math.round(k * icon.period * sampleRate)

    fun envelope(icon: HapticIcon, model: EnvelopeModel, index: Long, sampleRate: Int): Double {
        var max = 0.0
        for (k in 0 until icon.count) {
            val value = when (model) {
                EnvelopeModel.PAPER -> paperSingle(icon, (index - onset(icon, k, sampleRate)).toDouble() / sampleRate)
                EnvelopeModel.PROCESSING -> processingSingle(icon, index - onset(icon, k, sampleRate), sampleRate)
            }
            max = maxOf(max, value)
        }
        return max
    }

    fun carrier(icon: HapticIcon, model: EnvelopeModel, index: Long, sampleRate: Int): Double {
        val carrierIndex = if (model == EnvelopeModel.PROCESSING) index + 1 else index
        return sin(2.0 * PI * cycles(icon.frequency, carrierIndex, sampleRate))
    }

    fun sample(icon: HapticIcon, model: EnvelopeModel, index: Long, sampleRate: Int): Double =
        envelope(icon, model, index, sampleRate) * carrier(icon, model, index, sampleRate)

    /** PCM16 by the spec, written independently: x · 32767 (a double product) rounded half away from zero, clipped. */
    fun pcm(x: Double): Int {
        val rounded = BigDecimal(x * 32767.0).setScale(0, RoundingMode.HALF_UP).toInt()
        return rounded.coerceIn(-32767, 32767)
    }
}
