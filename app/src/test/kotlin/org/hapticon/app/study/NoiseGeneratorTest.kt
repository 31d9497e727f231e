package org.hapticon.app.study

import kotlin.math.PI
import kotlin.math.abs
import kotlin.math.cos
import kotlin.math.log10
import org.hapticon.gesture.extraction.Spectrum
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

/** The pure noise generator on the JVM: levels, seeds, the loop seam, and the spectral slope of each color. */
class NoiseGeneratorTest {
    private val rate = 48_000
    private val samples = rate * 10

    @Test
    fun white_isFlat_withinOneDecibelPerOctave() {
        val slopes = octaveSlopes(NoiseGenerator.samples(NoiseColor.WHITE, rate, samples, 1L, -12.0))
        println("white noise PSD change per octave, 125 Hz..16 kHz (dB): ${slopes.joinToString { "%.2f".format(it) }}")
        for ((i, slope) in slopes.withIndex()) assertEquals("octave $i", 0.0, slope, 1.0)
    }

    @Test
    fun pink_fallsThreeDecibelsPerOctave_withinOneDecibel() {
        val slopes = octaveSlopes(NoiseGenerator.samples(NoiseColor.PINK, rate, samples, 1L, -12.0))
        println("pink noise PSD change per octave, 125 Hz..16 kHz (dB): ${slopes.joinToString { "%.2f".format(it) }}")
        for ((i, slope) in slopes.withIndex()) assertEquals("octave $i", -3.01, slope, 1.0)
    }

    @Test
    fun render_hitsTheRequestedRmsLevel_andStaysInFullScale() {
        for (color in listOf(NoiseColor.WHITE, NoiseColor.PINK)) {
            val noise = NoiseGenerator.samples(color, rate, samples, 9L, -12.0)
            assertEquals(color.name, -12.0, NoiseGenerator.rmsDbfs(noise), 0.01)
            assertTrue(noise.all { it in -1f..1f && !it.isNaN() })
        }
    }

    @Test
    fun render_sameSeedSameNoise_otherSeedOtherNoise() {
        val a = NoiseGenerator.samples(NoiseColor.PINK, rate, 10_000, 3L, -20.0)
        assertArrayEquals(a, NoiseGenerator.samples(NoiseColor.PINK, rate, 10_000, 3L, -20.0), 0f)
        assertFalse(a.contentEquals(NoiseGenerator.samples(NoiseColor.PINK, rate, 10_000, 4L, -20.0)))
    }

    @Test
    fun loopSeam_jumpsNoMoreThanNeighbouringSamplesDo() {
        for (color in listOf(NoiseColor.WHITE, NoiseColor.PINK)) {
            val noise = NoiseGenerator.samples(color, rate, samples, 5L, -12.0)
            val largestStep = (1 until noise.size).maxOf { abs(noise[it] - noise[it - 1]) }
            assertTrue(color.name, abs(noise[0] - noise.last()) <= largestStep)
        }
    }

    @Test
    fun render_rejectsBadInput_withWhatWasWrong() {
        assertEquals(
            "no noise to render for OFF",
            assertThrows(IllegalArgumentException::class.java) { NoiseGenerator.samples(NoiseColor.OFF, rate, samples, 1L, -12.0) }.message,
        )
        assertEquals(
            "samples must be in 2049..67108864, was 2048",
            assertThrows(IllegalArgumentException::class.java) { NoiseGenerator.samples(NoiseColor.WHITE, rate, 2048, 1L, -12.0) }.message,
        )
        assertEquals(
            "rmsDbfs must be a finite value <= 0, was NaN",
            assertThrows(IllegalArgumentException::class.java) { NoiseGenerator.samples(NoiseColor.WHITE, rate, samples, 1L, Double.NaN) }.message,
        )
        assertEquals(
            "rmsDbfs must be a finite value <= 0, was 3.0",
            assertThrows(IllegalArgumentException::class.java) { NoiseGenerator.samples(NoiseColor.WHITE, rate, samples, 1L, 3.0) }.message,
        )
        assertEquals(
            "sampleRate must be > 0, was 0",
            assertThrows(IllegalArgumentException::class.java) { NoiseGenerator.samples(NoiseColor.WHITE, 0, samples, 1L, -12.0) }.message,
        )
        assertEquals(Double.NEGATIVE_INFINITY, NoiseGenerator.rmsDbfs(FloatArray(0)), 0.0)
    }

    @Test
    fun volume_isTheLevelBelowTheRenderedFile_cappedAtIt() {
        assertEquals(1f, NoiseFiles.volumeFor(-12.0), 0f)
        assertEquals(0.125893f, NoiseFiles.volumeFor(-30.0), 1e-6f)
        assertEquals("above the cap plays at the cap", 1f, NoiseFiles.volumeFor(0.0), 0f)
        assertEquals(0.003981f, NoiseFiles.volumeFor(-60.0), 1e-6f)
        assertEquals("below the floor plays at the floor", 0.003981f, NoiseFiles.volumeFor(-200.0), 1e-6f)
        assertEquals(0.003981f, NoiseFiles.volumeFor(Double.NaN), 1e-6f)
        assertEquals(1f, NoiseFiles.volumeFor(Double.POSITIVE_INFINITY), 0f)
    }

    /**
     * Welch PSD (8192-point Hann segments, half overlap), averaged per octave band from 125 Hz to 16 kHz, and the
     * change in dB from each band to the next: 0 for white, −3.01 for pink.
     */
    private fun octaveSlopes(x: FloatArray): List<Double> {
        val n = 8192
        val psd = DoubleArray(n / 2)
        val window = DoubleArray(n) { 0.5 - 0.5 * cos(2 * PI * it / n) }
        var start = 0
        while (start + n <= x.size) {
            val re = DoubleArray(n) { x[start + it] * window[it] }
            val im = DoubleArray(n)
            Spectrum.fft(re, im)
            for (k in psd.indices) psd[k] += re[k] * re[k] + im[k] * im[k]
            start += n / 2
        }
        val binHz = rate.toDouble() / n
        val bands = (0..7).map { octave ->
            val low = 125.0 * (1 shl octave)
            val bins = psd.indices.filter { it * binHz >= low && it * binHz < 2 * low }
            10 * log10(bins.sumOf { psd[it] } / bins.size)
        }
        return bands.zipWithNext { a, b -> b - a }
    }
}
