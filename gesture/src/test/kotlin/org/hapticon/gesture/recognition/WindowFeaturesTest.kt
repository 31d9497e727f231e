package org.hapticon.gesture.recognition

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test
import kotlin.math.ln
import kotlin.math.sqrt

class WindowFeaturesTest {
    private fun features(samples: DoubleArray, rate: Double = 2.0): DoubleArray {
        val out = DoubleArray(WindowFeatures.PER_CHANNEL)
        WindowFeatures(rate, samples.size).extract(samples, 0, samples.size, out, 0)
        return out
    }

    private fun stats(out: DoubleArray, series: Int) = out.copyOfRange(series * 11, series * 11 + 11)

    @Test
    fun valuesOfAHandComputedWindow() {
        val out = features(doubleArrayOf(1.0, 3.0, 2.0, 6.0))
        // sum, max, min, mean, median, std, variance, area, iqr, peaks, entropy
        assertArrayEquals(doubleArrayOf(12.0, 6.0, 1.0, 3.0, 2.5, sqrt(3.5), 3.5, 4.25, 2.0, 1.0, 2.0), stats(out, 0), 1e-12)
        val d1Variance = (sq(4 - 10.0 / 3) + sq(-2 - 10.0 / 3) + sq(8 - 10.0 / 3)) / 3
        assertArrayEquals(
            doubleArrayOf(10.0, 8.0, -2.0, 10.0 / 3, 4.0, sqrt(d1Variance), d1Variance, 2.0, 5.0, 0.0, ln(3.0) / ln(2.0)),
            stats(out, 1), 1e-12,
        )
        assertArrayEquals(doubleArrayOf(8.0, 20.0, -12.0, 4.0, 4.0, 16.0, 256.0, 2.0, 16.0, 0.0, 1.0), stats(out, 2), 1e-12)
    }

    private fun sq(x: Double) = x * x

    @Test
    fun peaksNeedProminenceOnBothSides() {
        // Range 10, so a peak must stand 2 above the troughs on both sides: 10 and 9 do, 1.5 does not; the
        // last rise is cut by the window end and not counted.
        val out = features(doubleArrayOf(0.0, 10.0, 0.0, 1.5, 0.5, 9.0, 0.0, 8.0))
        assertEquals(2.0, out[9], 0.0)
    }

    @Test
    fun constantAndZeroWindowsHaveNoSpreadPeaksOrEntropy() {
        for (value in doubleArrayOf(0.0, 5.0)) {
            val out = features(DoubleArray(10) { value }, rate = 10.0)
            assertArrayEquals(doubleArrayOf(10 * value, value, value, value, value, 0.0, 0.0, 0.9 * value, 0.0, 0.0, 0.0), stats(out, 0), 1e-12)
            assertArrayEquals(DoubleArray(22), out.copyOfRange(11, 33), 0.0)
        }
    }

    @Test
    fun oneSampleWindowHasZeroDerivativeFeatures() {
        val out = features(doubleArrayOf(7.0))
        assertArrayEquals(doubleArrayOf(7.0, 7.0, 7.0, 7.0, 7.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0), stats(out, 0), 0.0)
        assertArrayEquals(DoubleArray(22), out.copyOfRange(11, 33), 0.0)
    }

    @Test
    fun nonFiniteSamplesHoldTheLastFiniteValue() {
        val held = features(doubleArrayOf(Double.NaN, 1.0, Double.POSITIVE_INFINITY, 3.0, Double.NaN))
        assertArrayEquals(features(doubleArrayOf(1.0, 1.0, 1.0, 3.0, 3.0)), held, 0.0)
        val allNaN = features(DoubleArray(4) { Double.NaN })
        assertArrayEquals(DoubleArray(33), allNaN, 0.0)
    }

    @Test
    fun saturatedAndHugeSamplesStayFinite() {
        val saturated = features(DoubleArray(20) { if (it in 5..14) 40.0 else 0.0 }, rate = 100.0)
        assertEquals(400.0, saturated[0], 0.0)
        assertEquals(1.0, saturated[9], 0.0)
        val huge = features(doubleArrayOf(Double.MAX_VALUE, -Double.MAX_VALUE, Double.MAX_VALUE), rate = 1000.0)
        assertTrue(huge.all { it.isFinite() })
        assertEquals(WindowFeatures.SAMPLE_LIMIT, huge[1], 0.0)
    }

    @Test
    fun namesFollowTheOutputOrder() {
        val names = WindowFeatures.names(listOf("force", "accel_z"))
        assertEquals(66, names.size)
        assertEquals("force.sum", names[0])
        assertEquals("force.d1.entropy", names[21])
        assertEquals("accel_z.d2.entropy", names[65])
    }

    @Test
    fun rejectsWindowsThatDoNotFit() {
        val extractor = WindowFeatures(100.0, 4)
        val out = DoubleArray(33)
        assertThrows(IllegalArgumentException::class.java) { extractor.extract(DoubleArray(10), 0, 5, out, 0) }
        assertThrows(IllegalArgumentException::class.java) { extractor.extract(DoubleArray(10), 0, 0, out, 0) }
        assertThrows(IllegalArgumentException::class.java) { extractor.extract(DoubleArray(3), 0, 4, out, 0) }
        assertThrows(IllegalArgumentException::class.java) { extractor.extract(DoubleArray(4), 0, 4, out, 1) }
    }
}
