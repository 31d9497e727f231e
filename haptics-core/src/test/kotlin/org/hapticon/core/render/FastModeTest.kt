package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import kotlin.math.abs

class FastModeTest {
    private val longest = HapticIcon.LONGEST_ALLOWED
    private val rates = listOf(8_000, 44_100, 48_000, 96_000, 192_000)
    private val notes = listOf(0.0, 21.0, 57.0, 65.0, 100.0, 127.0)

    /** Largest |FAST − EXACT| over the two full streams; also checks they have the same length. */
    private fun maxDifference(icon: HapticIcon, fs: Int, model: EnvelopeModel): Double {
        val exact = IconRenderer(icon, fs, model, RenderMode.EXACT).stream()
        val fast = IconRenderer(icon, fs, model, RenderMode.FAST).stream()
        val a = FloatArray(4096)
        val b = FloatArray(4096)
        var worst = 0.0
        var total = 0L
        while (true) {
            val n = exact.read(a)
            val m = fast.read(b)
            assertEquals(n, m)
            if (n < 0) break
            for (j in 0 until n) worst = maxOf(worst, abs(a[j].toDouble() - b[j].toDouble()))
            total += n
        }
        assertEquals(exact.totalSamples, total)
        return worst
    }

    /** Largest |FAST − EXACT| over the two full streams read as doubles (before narrowing to float). */
    private fun maxDoubleDifference(icon: HapticIcon, fs: Int, model: EnvelopeModel): Double {
        val exact = IconRenderer(icon, fs, model, RenderMode.EXACT).stream()
        val fast = IconRenderer(icon, fs, model, RenderMode.FAST).stream()
        val a = DoubleArray(4096)
        val b = DoubleArray(4096)
        var worst = 0.0
        var total = 0L
        while (true) {
            val n = exact.read(a)
            assertEquals(n, fast.read(b))
            if (n < 0) break
            for (j in 0 until n) worst = maxOf(worst, abs(a[j] - b[j]))
            total += n
        }
        assertEquals(exact.totalSamples, total)
        return worst
    }

    /** Rates and notes of the double-precision checks, without the pairs at or above Nyquist (note 127 at 8 kHz). */
    private val doubleCases = listOf(8_000, 44_100, 192_000).flatMap { fs ->
        listOf(0.0, 57.0, 127.0).filter { note -> HapticIcon("n", 0.0, 0.1, 1.0, 0.0, note).frequency < fs / 2.0 }.map { fs to it }
    }

    @Test
    fun doubleCases_areEightRateNotePairs() {
        assertEquals(8, doubleCases.size)
    }

    @Test
    fun fastDoubles_fullScaleThirtySecondsBothModels_staysWithin1e9OfExact() {
        // Envelope 1 throughout, so the difference is the carrier's alone, over the longest allowed stream.
        for ((fs, note) in doubleCases) for (model in EnvelopeModel.values()) {
            val icon = HapticIcon("full-scale", 0.0, HapticIcon.MAX_DURATION_SECONDS, 1.0, 0.0, note)
            val worst = maxDoubleDifference(icon, fs, model)
            assertTrue("note $note $fs Hz $model: $worst", worst <= 1e-9)
        }
    }

    @Test
    fun fastDoubles_longestIconBothModels_staysWithin1e9OfExact() {
        for ((fs, note) in doubleCases) for (model in EnvelopeModel.values()) {
            val worst = maxDoubleDifference(longest.copy(note = note), fs, model)
            assertTrue("longest note $note $fs Hz $model: $worst", worst <= 1e-9)
        }
    }

    @Test
    fun fastStream_allRatesNotesPresetsAndModels_staysWithin1e6OfExact() {
        for (fs in rates) for (note in notes) {
            if (440.0 * Math.pow(2.0, (note - 69.0) / 12.0) >= fs / 2.0) continue
            for (preset in HapticIcon.PRESETS) for (model in EnvelopeModel.values()) {
                val icon = preset.copy(note = note)
                val worst = maxDifference(icon, fs, model)
                assertTrue("${icon.name} note $note $fs Hz $model: $worst", worst <= 1e-6)
            }
        }
    }

    @Test
    fun fastStream_longestIconAllRatesAndNotes_staysWithin1e6OfExact() {
        for (fs in rates) for (note in notes) {
            if (440.0 * Math.pow(2.0, (note - 69.0) / 12.0) >= fs / 2.0) continue
            val worst = maxDifference(longest.copy(note = note), fs, EnvelopeModel.PAPER)
            assertTrue("longest note $note $fs Hz: $worst", worst <= 1e-6)
        }
    }

    @Test
    fun fastStream_longestIconProcessingAt192000_staysWithin1e6OfExactDoubles() {
        // Against the double-precision reference, not just the float stream.
        val renderer = IconRenderer(longest.copy(note = 127.0), 192_000, EnvelopeModel.PROCESSING, RenderMode.FAST)
        val stream = renderer.stream()
        val block = FloatArray(4096)
        var worst = 0.0
        var index = 0L
        while (true) {
            val n = stream.read(block)
            if (n < 0) break
            for (j in 0 until n) {
                // Every 7th sample keeps the reference cost down while covering all anchor offsets.
                if ((index + j) % 7 == 0L) worst = maxOf(worst, abs(block[j] - renderer.sampleAt(index + j)))
            }
            index += n
        }
        assertEquals(5_760_000L, index)
        assertTrue("worst $worst", worst <= 1e-6)
    }
}
