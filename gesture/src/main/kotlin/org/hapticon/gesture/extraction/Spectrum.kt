package org.hapticon.gesture.extraction

import kotlin.math.PI
import kotlin.math.cos
import kotlin.math.ln
import kotlin.math.roundToInt
import kotlin.math.sin

/** Spectral helpers for the carrier: an in-place radix-2 FFT and a Hann-windowed dominant-frequency estimate. */
public object Spectrum {
    /**
     * In-place iterative radix-2 Cooley–Tukey FFT of ([re], [im]); both must have the same power-of-two
     * length (1 is allowed).
     */
    public fun fft(re: DoubleArray, im: DoubleArray) {
        val n = re.size
        require(im.size == n) { "real and imaginary parts differ in length: $n and ${im.size}" }
        require(n > 0 && n and (n - 1) == 0) { "FFT length must be a power of two, was $n" }
        var j = 0
        for (i in 1 until n) {
            var bit = n shr 1
            while (j and bit != 0) {
                j = j xor bit
                bit = bit shr 1
            }
            j = j or bit
            if (i < j) {
                val tr = re[i]; re[i] = re[j]; re[j] = tr
                val ti = im[i]; im[i] = im[j]; im[j] = ti
            }
        }
        var length = 2
        while (length <= n) {
            val angle = -2.0 * PI / length
            val half = length / 2
            // Twiddles computed directly per k (not by repeated rotation) so rounding does not accumulate.
            for (k in 0 until half) {
                val wr = cos(angle * k)
                val wi = sin(angle * k)
                var start = 0
                while (start < n) {
                    val a = start + k
                    val b = a + half
                    val xr = re[b] * wr - im[b] * wi
                    val xi = re[b] * wi + im[b] * wr
                    re[b] = re[a] - xr
                    im[b] = im[a] - xi
                    re[a] += xr
                    im[a] += xi
                    start += length
                }
            }
            length = length shl 1
        }
    }

    /**
     * The strongest frequency in Hz of `samples[from, to)` at [sampleRate]: mean removed, Hann window,
     * zero-padded to a power of two at least [MIN_FFT_LENGTH], then the peak bin refined by parabolic
     * interpolation of the log magnitudes (exact for a Gaussian peak, close for Hann's main lobe). Returns
     * 0.0 when the span is silent after removing the mean.
     */
    public fun dominantFrequency(samples: DoubleArray, sampleRate: Double, from: Int = 0, to: Int = samples.size): Double {
        require(from in 0..to && to <= samples.size) { "span [$from, $to) is outside 0..${samples.size}" }
        val length = to - from
        if (length < 2) return 0.0
        var n = MIN_FFT_LENGTH
        while (n < length) n = n shl 1
        var mean = 0.0
        for (i in from until to) mean += samples[i]
        mean /= length
        val re = DoubleArray(n)
        val im = DoubleArray(n)
        for (i in 0 until length) {
            val window = 0.5 - 0.5 * cos(2.0 * PI * i / (length - 1))
            re[i] = (samples[from + i] - mean) * window
        }
        fft(re, im)
        val bins = n / 2
        var peak = 0
        var peakPower = 0.0
        for (k in 1 until bins) {
            val power = re[k] * re[k] + im[k] * im[k]
            if (power > peakPower) {
                peakPower = power
                peak = k
            }
        }
        if (peak == 0 || peakPower < 1e-24) return 0.0
        var offset = 0.0
        if (peak + 1 < bins) {
            val a = ln(re[peak - 1] * re[peak - 1] + im[peak - 1] * im[peak - 1] + 1e-300)
            val b = ln(peakPower)
            val c = ln(re[peak + 1] * re[peak + 1] + im[peak + 1] * im[peak + 1] + 1e-300)
            val denominator = a - 2 * b + c
            if (denominator < 0.0) offset = (0.5 * (a - c) / denominator).coerceIn(-0.5, 0.5)
        }
        return (peak + offset) * sampleRate / n
    }

    /**
     * MIDI note of [frequency] Hz: round(69 + 12·log2(f/440)), clamped to 0..127 and to the highest note
     * whose frequency is below the Nyquist frequency of [sampleRate].
     */
    public fun noteOf(frequency: Double, sampleRate: Double): Int {
        require(frequency.isFinite() && frequency > 0.0) { "frequency must be finite and > 0 Hz, was $frequency" }
        val note = (69.0 + 12.0 * ln(frequency / 440.0) / ln(2.0)).roundToInt().coerceIn(0, 127)
        var clamped = note
        while (clamped > 0 && org.hapticon.core.midiNoteToHz(clamped.toDouble()) >= sampleRate / 2.0) clamped--
        return clamped
    }

    /** Smallest FFT length used, so a short span still gets a finely spaced (interpolated) spectrum. */
    public const val MIN_FFT_LENGTH: Int = 4096
}
