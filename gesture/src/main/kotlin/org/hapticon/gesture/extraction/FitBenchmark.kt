package org.hapticon.gesture.extraction

import java.util.Locale
import java.util.Random
import kotlin.math.abs
import kotlin.math.sqrt

/**
 * Parameter recovery of one envelope method at one SNR over a set of random icons: mean absolute errors,
 * exact-match rates, and the envelope's own error. [failures] counts fits that threw.
 */
public class RecoveryRow(
    /** Envelope method. */
    public val method: EnvelopeMethod,
    /** Noise level in dB. */
    public val snrDb: Double,
    /** Icons fitted. */
    public val trials: Int,
    /** RMS of (recovered − true envelope) over the icon's span, relative to the icon's level, averaged. */
    public val envelopeError: Double,
    /** Mean |error| of attack in seconds. */
    public val attackError: Double,
    /** Mean |error| of sustain in seconds. */
    public val sustainError: Double,
    /** Mean |error| of release in seconds. */
    public val releaseError: Double,
    /** Mean |error| of level (full-scale reference). */
    public val levelError: Double,
    /** Mean |error| of period in seconds, over icons with more than one repetition. */
    public val periodError: Double,
    /** Fraction of icons whose note came out exactly. */
    public val noteExact: Double,
    /** Fraction of icons whose count came out exactly. */
    public val countExact: Double,
    /** Mean estimated SNR in dB; null when no fit could estimate it. */
    public val estimatedSnrDb: Double?,
    /** Largest |attack error| in seconds. */
    public val attackWorst: Double,
    /** Fits that threw. */
    public val failures: Int,
)

/**
 * The synthetic evaluation: [trials] random icons ([NoisyIconRenders.randomIcon], seeded by [seed]) at
 * 44.1 kHz with white noise at each SNR, fitted with each envelope method (level against full scale, so it
 * can be compared), errors averaged. Deterministic for a given seed.
 */
public object FitBenchmark {
    /** The SNRs of the evaluation, in dB. */
    public val SNRS: List<Double> = listOf(10.0, 20.0, 30.0, 40.0)

    /** Runs the evaluation; rows in method order, then SNR order. */
    public fun run(trials: Int, seed: Long, snrs: List<Double> = SNRS, methods: List<EnvelopeMethod> = EnvelopeMethod.entries): List<RecoveryRow> {
        require(trials >= 1) { "trials must be >= 1, was $trials" }
        val rows = ArrayList<RecoveryRow>()
        for (method in methods) {
            for ((s, snr) in snrs.withIndex()) {
                // The same icons and noise for every method, so the methods are compared on equal inputs.
                val icons = Random(seed)
                val noise = Random(seed * 31 + s)
                val options = FitOptions(envelope = method, levelReference = LevelReference.FullScale)
                val acc = Accumulator()
                repeat(trials) {
                    val icon = NoisyIconRenders.randomIcon(icons)
                    val gesture = NoisyIconRenders.render(icon, snr, noise)
                    try {
                        val fit = IconFitter.fit(gesture.toRecording(), options = options)
                        acc.add(gesture, fit, IconFitter.envelope(gesture.samples(), gesture.sampleRate.toDouble(), options))
                    } catch (e: IllegalArgumentException) {
                        acc.failures++
                    }
                }
                rows += acc.row(method, snr, trials)
            }
        }
        return rows
    }

    /** [rows] as a fixed-width text table (times in ms). */
    public fun format(rows: List<RecoveryRow>): String {
        val out = StringBuilder()
        out.append(String.format(Locale.ROOT, "%-8s %4s %6s %8s %8s %8s %8s %8s %7s %7s %8s %8s %5s%n",
            "envelope", "SNR", "env.err", "attack", "sustain", "release", "level", "period", "note=", "count=", "SNR est", "atk.max", "fail"))
        out.append(String.format(Locale.ROOT, "%-8s %4s %6s %8s %8s %8s %8s %8s %7s %7s %8s %8s %5s%n",
            "", "dB", "%", "ms", "ms", "ms", "abs", "ms", "%", "%", "dB", "ms", ""))
        for (r in rows) {
            out.append(String.format(Locale.ROOT, "%-8s %4.0f %6.2f %8.2f %8.2f %8.2f %8.4f %8.3f %7.1f %7.1f %8s %8.2f %5d%n",
                r.method.name.lowercase(), r.snrDb, 100 * r.envelopeError, 1000 * r.attackError, 1000 * r.sustainError,
                1000 * r.releaseError, r.levelError, 1000 * r.periodError, 100 * r.noteExact, 100 * r.countExact,
                r.estimatedSnrDb?.let { String.format(Locale.ROOT, "%.1f", it) } ?: "-", 1000 * r.attackWorst, r.failures))
        }
        return out.toString()
    }

    private class Accumulator {
        var fits = 0
        var failures = 0
        var envelope = 0.0
        var attack = 0.0
        var sustain = 0.0
        var release = 0.0
        var level = 0.0
        var period = 0.0
        var periodCount = 0
        var notes = 0
        var counts = 0
        var snr = 0.0
        var snrCount = 0
        var attackWorst = 0.0

        fun add(gesture: NoisyIconRender, fit: IconFit, recovered: DoubleArray) {
            val icon = gesture.icon
            val got = fit.icon
            fits++
            val truth = gesture.trueEnvelope()
            var sum = 0.0
            val from = gesture.padSamples
            val to = truth.size - gesture.padSamples
            for (i in from until to) sum += (recovered[i] - truth[i]) * (recovered[i] - truth[i])
            envelope += sqrt(sum / (to - from)) / icon.level
            attack += abs(got.attack - icon.attack)
            attackWorst = maxOf(attackWorst, abs(got.attack - icon.attack))
            sustain += abs(got.sustain - icon.sustain)
            release += abs(got.release - icon.release)
            level += abs(got.level - icon.level)
            if (icon.count > 1 && got.count > 1) {
                period += abs(got.period - icon.period)
                periodCount++
            }
            if (got.note == icon.note) notes++
            if (got.count == icon.count) counts++
            fit.report.snrDb?.let { snr += it; snrCount++ }
        }

        fun row(method: EnvelopeMethod, snrDb: Double, trials: Int): RecoveryRow {
            val n = maxOf(1, fits).toDouble()
            return RecoveryRow(
                method, snrDb, trials, envelope / n, attack / n, sustain / n, release / n, level / n,
                if (periodCount > 0) period / periodCount else 0.0, notes / n, counts / n,
                if (snrCount > 0) snr / snrCount else null, attackWorst, failures,
            )
        }
    }
}
