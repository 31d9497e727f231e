package org.hapticon.app.study

import java.util.Random
import kotlin.math.log10
import kotlin.math.pow
import kotlin.math.sqrt
import org.hapticon.core.render.FloatArraySampleStream
import org.hapticon.core.render.SampleStream

/** The masking noise of a protocol; [OFF] plays nothing. */
enum class NoiseColor(val label: String) {
    OFF("Off"),

    /** Equal power per hertz: a flat spectrum. */
    WHITE("White noise"),

    /** Equal power per octave: the spectrum falls 3 dB per octave, which sounds even to the ear. */
    PINK("Pink noise"),
    ;

    companion object {
        /** The color named [name] (an enum name), or [OFF] for an unknown name from older or newer storage. */
        fun of(name: String): NoiseColor = entries.firstOrNull { it.name == name } ?: OFF
    }
}

/**
 * Seeded white and pink noise, pure Kotlin. White is Gaussian (java.util.Random, the same sequence on every JVM for a
 * seed); pink is that white noise through Paul Kellet's refined filter (seven first-order sections whose sum is within
 * ±0.05 dB of −3 dB/octave from 9.2 Hz up at 44.1 kHz; at 48 kHz the poles shift by under 10 %, well inside ±1 dB).
 */
object NoiseGenerator {
    /** Samples of the crossfade that joins a rendering's end to its start, so that a looped file does not click. */
    const val LOOP_CROSSFADE_SAMPLES: Int = 2048

    /**
     * [samples] samples of [color] noise at [sampleRate] from [seed], scaled to an RMS of [rmsDbfs] (dB re full scale,
     * a full-scale sine being −3 dBFS RMS) and clipped to ±1. The end flows into the start (an equal-power crossfade
     * of [LOOP_CROSSFADE_SAMPLES]), so the result loops seamlessly. Throws [IllegalArgumentException] when [color] is
     * [NoiseColor.OFF], [samples] is not above the crossfade length or over 2^26, [sampleRate] is not positive, or
     * [rmsDbfs] is not a finite value ≤ 0.
     */
    fun samples(color: NoiseColor, sampleRate: Int, samples: Int, seed: Long, rmsDbfs: Double): FloatArray {
        require(color != NoiseColor.OFF) { "no noise to render for OFF" }
        require(sampleRate > 0) { "sampleRate must be > 0, was $sampleRate" }
        require(samples in (LOOP_CROSSFADE_SAMPLES + 1)..(1 shl 26)) {
            "samples must be in ${LOOP_CROSSFADE_SAMPLES + 1}..${1 shl 26}, was $samples"
        }
        require(rmsDbfs.isFinite() && rmsDbfs <= 0.0) { "rmsDbfs must be a finite value <= 0, was $rmsDbfs" }
        val raw = DoubleArray(samples + LOOP_CROSSFADE_SAMPLES)
        val random = Random(seed)
        val pink = if (color == NoiseColor.PINK) KelletPinkFilter() else null
        // Let the pink filter's slowest section (pole 0.99886, ~880 samples) settle before the first kept sample.
        if (pink != null) repeat(8 * 1024) { pink.next(random.nextGaussian()) }
        for (i in raw.indices) {
            val white = random.nextGaussian()
            raw[i] = pink?.next(white) ?: white
        }
        val fade = LOOP_CROSSFADE_SAMPLES
        for (i in 0 until fade) {
            val t = (i + 0.5) / fade
            raw[i] = raw[i] * sqrt(t) + raw[samples + i] * sqrt(1 - t)
        }
        var sumSquares = 0.0
        for (i in 0 until samples) sumSquares += raw[i] * raw[i]
        val gain = 10.0.pow(rmsDbfs / 20) / sqrt(sumSquares / samples)
        return FloatArray(samples) { (raw[it] * gain).coerceIn(-1.0, 1.0).toFloat() }
    }

    /** The RMS level of [samples] in dBFS; −∞ for silence or an empty array. */
    fun rmsDbfs(samples: FloatArray): Double {
        if (samples.isEmpty()) return Double.NEGATIVE_INFINITY
        var sum = 0.0
        for (x in samples) sum += x.toDouble() * x
        return 10 * log10(sum / samples.size)
    }

    /** [samples] as a [SampleStream] at [sampleRate], for [org.hapticon.core.io.WavWriter]. */
    fun stream(samples: FloatArray, sampleRate: Int): SampleStream = FloatArraySampleStream(samples, sampleRate)

    /** Paul Kellet's refined pink filter ("instrumentation grade"), from the music-dsp archive. */
    private class KelletPinkFilter {
        private var b0 = 0.0
        private var b1 = 0.0
        private var b2 = 0.0
        private var b3 = 0.0
        private var b4 = 0.0
        private var b5 = 0.0
        private var b6 = 0.0

        fun next(white: Double): Double {
            b0 = 0.99886 * b0 + white * 0.0555179
            b1 = 0.99332 * b1 + white * 0.0750759
            b2 = 0.96900 * b2 + white * 0.1538520
            b3 = 0.86650 * b3 + white * 0.3104856
            b4 = 0.55000 * b4 + white * 0.5329522
            b5 = -0.7616 * b5 - white * 0.0168980
            val pink = b0 + b1 + b2 + b3 + b4 + b5 + b6 + white * 0.5362
            b6 = white * 0.115926
            return pink
        }
    }
}
