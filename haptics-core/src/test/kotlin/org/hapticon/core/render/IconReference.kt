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

    /**
     * PROCESSING: one repetition at local sample n, transliterated line by line from JSyn's
     * `VariableRateMonoReader.generate` (starved start, running double phase sum, `while (phase >= 1.0)`
     * carry) and `SegmentedEnvelope.getRateScaler` (1 / max(duration, framePeriod)), playing Processing
     * Sound's `Env.play` frames built from float parameters, and cut at the first 8-frame JSyn block start n with
     * n · framePeriod ≥ A+S+R (as floats): `SynthesisEngine` runs the scheduled disconnection only there.
     */
    fun processingSingle(icon: HapticIcon, n: Long, sampleRate: Int): Double {
        val values = processingCache.getOrPut(icon to sampleRate) { processingRepetition(icon, sampleRate) }
        return if (n < 0 || n >= values.size) 0.0 else values[n.toInt()]
    }

    private val processingCache = HashMap<Pair<HapticIcon, Int>, DoubleArray>()

    private fun processingRepetition(icon: HapticIcon, sampleRate: Int): DoubleArray {
        val framePeriod = 1.0 / sampleRate
        val frames = ArrayDeque(
            listOf(
                icon.attack.toFloat().toDouble() to 1.0,
                icon.sustain.toFloat().toDouble() to (icon.level.toFloat() * 1.0f).toDouble(),
                icon.release.toFloat().toDouble() to 0.0,
            ),
        )
        val stamp = (icon.attack.toFloat() + icon.sustain.toFloat() + icon.release.toFloat()).toDouble()
        var disconnect = 0L
        while (disconnect * framePeriod < stamp) disconnect += 8
        val out = DoubleArray(disconnect.toInt())
        var phase = 0.0
        var source = 0.0
        var target = 0.0
        var current = 0.0
        var baseIncrement: Double
        fun advanceToNextFrame(): Double {
            val frame = frames.removeFirstOrNull() ?: run { phase = 0.0; return 0.0 }
            target = frame.second
            var duration = frame.first
            if (duration < framePeriod) duration = framePeriod
            return framePeriod * (1.0 / duration)
        }
        // i == 0 of the reader's first block, starved: source = target = current, phase 0.
        source = current
        target = current
        baseIncrement = advanceToNextFrame()
        var i = 0
        while (i < out.size) {
            if (i > 0 && phase >= 1.0) {
                while (phase >= 1.0) {
                    source = target
                    phase -= 1.0
                    baseIncrement = advanceToNextFrame()
                }
            }
            current = ((target - source) * phase) + source
            out[i] = current
            phase += baseIncrement * 1.0
            i++
        }
        return out
    }

    /** Repetition k starts on the sample nearest to k · period (the documented rendering rule). */
    fun onset(icon: HapticIcon, k: Int, sampleRate: Int): Long = Math.round(k * icon.period * sampleRate)

    fun envelope(icon: HapticIcon, model: EnvelopeModel, index: Long, sampleRate: Int): Double {
        // PAPER: the larger repetition wins; PROCESSING: JSyn's InputMixingBlockPart adds every connected reader.
        var combined = 0.0
        for (k in 0 until icon.count) {
            combined = when (model) {
                EnvelopeModel.PAPER -> maxOf(combined, paperSingle(icon, (index - onset(icon, k, sampleRate)).toDouble() / sampleRate))
                EnvelopeModel.PROCESSING -> combined + processingSingle(icon, index - onset(icon, k, sampleRate), sampleRate)
            }
        }
        return combined
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
