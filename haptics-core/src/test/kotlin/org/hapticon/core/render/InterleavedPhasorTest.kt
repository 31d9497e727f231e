package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.hapticon.core.signal.SampleClock
import org.hapticon.core.signal.sineOfCycles
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import kotlin.math.abs
import kotlin.math.ln

class InterleavedPhasorTest {
    /** One float32 step just below full scale: 2^-24. */
    private val floatStep = Math.scalb(1.0, -24)
    private val rates = listOf(8_000, 22_050, 44_100, 48_000, 96_000, 192_000)

    /** Largest |FAST − EXACT| between the float32 samples of full-scale (envelope 1) streams of [icon]. */
    private fun maxFloatDifference(icon: HapticIcon, fs: Int, model: EnvelopeModel, block: Int = 4096): Double {
        val exact = IconRenderer(icon, fs, model, RenderMode.EXACT).stream()
        val fast = IconRenderer(icon, fs, model, RenderMode.FAST).stream()
        val a = FloatArray(block)
        val b = FloatArray(block)
        var worst = 0.0
        while (true) {
            val n = exact.read(a)
            assertEquals(n, fast.read(b, 0, maxOf(n, 0)).let { if (n < 0) -1 else it })
            if (n < 0) return worst
            for (j in 0 until n) worst = maxOf(worst, abs(a[j].toDouble() - b[j].toDouble()))
        }
    }

    private fun fullScale(note: Double, seconds: Double) = HapticIcon("full-scale", 0.0, seconds, 1.0, 0.0, note)

    @Test fun fastFloats_everyRateAndNote0To127BelowNyquist_withinOneFloatStepOfExact() {
        var cases = 0
        for (fs in rates) for (note in 0..127) {
            val icon = fullScale(note.toDouble(), 0.05)
            if (icon.frequency >= fs / 2.0) continue
            for (model in EnvelopeModel.values()) {
                val worst = maxFloatDifference(icon, fs, model, block = 1000) // blocks off the 4-sample groups
                assertTrue("note $note at $fs Hz, $model: $worst", worst <= floatStep)
                cases++
            }
        }
        assertEquals(2 * (108 + 125 + 4 * 128), cases) // every note below Nyquist (0..107 at 8 kHz, 0..124 at 22.05 kHz), both models
    }

    @Test fun fastFloats_carrierJustBelowNyquist_withinOneFloatStepOfExact() {
        // Only these rates have their Nyquist frequency within MIDI notes 0..127 (note 127 is 12.5 kHz).
        for (fs in listOf(8_000, 11_025, 16_000, 22_050)) {
            val note = 69.0 + 12.0 * ln(fs / 2.0 * (1 - 1e-9) / 440.0) / ln(2.0)
            val icon = fullScale(note, 1.0)
            assertTrue(icon.frequency < fs / 2.0 && icon.frequency > fs / 2.0 * (1 - 1e-8))
            val worst = maxFloatDifference(icon, fs, EnvelopeModel.PAPER, block = 333)
            assertTrue("Nyquist at $fs Hz: $worst", worst <= floatStep)
        }
    }

    @Test fun kernel_hoursIntoTheStream_matchesTheExactPhaseWithinOneFloatStep() {
        for (fs in listOf(8_000, 192_000)) for (note in listOf(0.0, 57.0, 107.0)) {
            val clock = SampleClock(440.0 * Math.pow(2.0, (note - 69) / 12), fs)
            val start = 3L * 3600 * fs + 17 // three hours in
            val phasor = InterleavedPhasor(clock)
            phasor.anchor(clock.cyclesAt(start))
            val out = DoubleArray(IconSynthesizer.FAST_ANCHOR_INTERVAL)
            phasor.fill(out, 0, out.size, 1.0, 0.0, 1.0, 0.0, 0.0)
            for (j in out.indices) {
                val exact = sineOfCycles(clock.cyclesAt(start + j))
                assertTrue("note $note at $fs Hz, sample $j: ${out[j]} vs $exact", abs(out[j] - exact) <= 1e-11)
                assertTrue(abs(out[j].toFloat().toDouble() - exact.toFloat().toDouble()) <= floatStep)
            }
        }
    }

    @Test fun kernel_splitIntoOddPieces_writesBitIdenticalSamplesToOnePiece() {
        val clock = SampleClock(261.6255653005986, 44_100)
        val whole = DoubleArray(1024)
        InterleavedPhasor(clock).apply { anchor(0.3) }.fill(whole, 0, whole.size, 0.1, 0.002, 0.9, -0.001, 5.0)
        val pieces = DoubleArray(1024)
        val phasor = InterleavedPhasor(clock).apply { anchor(0.3) }
        var at = 0
        var size = 1
        while (at < pieces.size) {
            val n = minOf(size, pieces.size - at)
            phasor.fill(pieces, at, n, 0.1, 0.002, 0.9, -0.001, 5.0 + at)
            at += n
            size = size % 7 + 1 // 1, 2, ..., 7, 1, ...: every remainder of a group of four
        }
        assertArrayEquals(whole, pieces, 0.0)
    }

    @Test fun kernel_oneLineDominatingTheChunk_writesBitIdenticalSamplesToTheTwoLineMax() {
        // Pieces under 8 samples always take the two-line kernel; the whole chunk takes the one-line one.
        val clock = SampleClock(440.0, 48_000)
        for ((lines, name) in listOf(doubleArrayOf(0.2, 1e-4, 0.1, -1e-4) to "rising on top", doubleArrayOf(0.0, 0.0, 0.7, -2e-4) to "falling on top")) {
            val (rv, rsl, fv, fsl) = lines.toList()
            val whole = DoubleArray(1024)
            InterleavedPhasor(clock).apply { anchor(0.1) }.fill(whole, 0, whole.size, rv, rsl, fv, fsl, 3.0)
            val pieces = DoubleArray(1024)
            val phasor = InterleavedPhasor(clock).apply { anchor(0.1) }
            var at = 0
            while (at < pieces.size) {
                val n = minOf(5, pieces.size - at)
                phasor.fill(pieces, at, n, rv, rsl, fv, fsl, 3.0 + at)
                at += n
            }
            assertArrayEquals(name, pieces, whole, 0.0)
            assertEquals(name, runValue(rv, rsl, fv, fsl, 1000.0) * sineOfCycles((0.1 + 997 * 440.0 / 48_000) % 1.0), whole[997], 1e-12)
        }
    }

    @Test fun kernel_envelope_isTheRunValueAtEachWholeIndex() {
        val clock = SampleClock(100.0, 8_000)
        val out = DoubleArray(7)
        InterleavedPhasor(clock).apply { anchor(0.25) }.fill(out, 0, out.size, 0.0, 0.125, 0.5, 0.0, 2.0)
        // Lines 0.125·m and 0.5 from m = 2: max gives 0.25, 0.375, 0.5, 0.625, ...; carrier from a quarter cycle.
        for (j in out.indices) {
            val envelope = maxOf(0.125 * (2 + j), 0.5)
            assertEquals(envelope * sineOfCycles((0.25 + j * 100.0 / 8_000) % 1.0), out[j], 1e-15)
        }
    }

    @Test fun fastStream_floatReads_areTheDoubleReadsNarrowed() {
        val renderer = IconRenderer(HapticIcon.KNOCK, 44_100, EnvelopeModel.PROCESSING, RenderMode.FAST)
        val doubles = DoubleArray(renderer.sampleCount.toInt())
        assertEquals(doubles.size, renderer.stream().read(doubles, 0, doubles.size))
        val floats = FloatArray(doubles.size)
        val stream = renderer.stream()
        var at = 0
        while (at < floats.size) at += stream.read(floats, at, minOf(3, floats.size - at))
        assertArrayEquals(FloatArray(doubles.size) { doubles[it].toFloat() }, floats, 0f)
    }
}
