package org.hapticon.core.signal

import org.junit.Assert.assertEquals
import org.junit.Assert.assertSame
import org.junit.Assert.assertTrue
import org.junit.Test
import kotlin.math.PI
import kotlin.math.sin

class SignalAlgebraTest {
    private val tolerance = 1e-12

    @Test
    fun product_sineTimesAsr_endsWithTheEnvelope() {
        val tone = Sine(100.0) * Asr(0.1, 0.2, 0.3, 0.5)
        assertEquals(0.6, tone.length, tolerance)
        // t = 0.2025 s: envelope 0.5 (sustain), sine at 20.25 cycles = sin(π/2) = 1.
        assertEquals(0.5, tone.sample(0.2025), tolerance)
        // t = 0.05 s: half way up the attack, 0.25; sine at 5 cycles = 0.
        assertEquals(0.0, tone.sample(0.05), tolerance)
        // t = 0.4525 s: release 0.5·(0.6 − 0.4525)/0.3 = 0.245833…, sine at 45.25 cycles = 1.
        assertEquals(0.5 * 0.1475 / 0.3, tone.sample(0.4525), tolerance)
    }

    @Test
    fun product_lengthIsTheShorterFactor() {
        assertEquals(0.25, (Silence(0.25) * Silence(2.0)).length, 0.0)
        assertEquals(1.5, (Square(3.0) * Asr(0.5, 0.5, 0.5)).length, 0.0)
    }

    @Test
    fun sum_lengthIsTheLongerTermAndValuesAdd() {
        val sum = Asr(0.0, 1.0, 0.0, 0.25) + Asr(1.0, 1.0, 0.0, 0.5)
        assertEquals(2.0, sum.length, 0.0)
        // t = 0.5: 0.25 + 0.25 (half way up the second attack).
        assertEquals(0.5, sum.sample(0.5), tolerance)
        // t = 1.5: first has ended, second sustains at 0.5.
        assertEquals(0.5, sum.sample(1.5), tolerance)
    }

    @Test
    fun times_scalarOnAGain_foldsIntoOneGain() {
        val sine = Sine(10.0)
        val scaled = 0.5 * (sine * 4.0)
        assertTrue(scaled is Gain)
        scaled as Gain
        assertSame(sine, scaled.signal)
        assertEquals(2.0, scaled.gain, 0.0)
        // 10 Hz at t = 0.025 s is a quarter cycle: 2 · 1.
        assertEquals(2.0, scaled.sample(0.025), tolerance)
    }

    @Test
    fun oscillators_atQuarterCycles_haveTheirDefiningValues() {
        // 4 Hz: a quarter cycle is 62.5 ms.
        assertEquals(0.0, Sine(4.0).sample(0.0), 0.0)
        assertEquals(1.0, Sine(4.0).sample(0.0625), tolerance)
        assertEquals(1.0, Triangle(4.0).sample(0.0625), tolerance)
        assertEquals(-0.5, Triangle(4.0).sample(0.21875), tolerance)
        assertEquals(1.0, Square(4.0).sample(0.1), 0.0)
        assertEquals(-1.0, Square(4.0).sample(0.2), 0.0)
        assertEquals(Double.POSITIVE_INFINITY, Sine(4.0).length, 0.0)
    }

    @Test
    fun envelope_zeroLengthSegments_areSkippedAndStepsTakeTheLaterKey() {
        val noAttack = Asr(0.0, 1.0, 0.5, 0.8)
        assertEquals(0.8, noAttack.sample(0.0), 0.0)
        assertEquals(0.4, noAttack.sample(1.25), tolerance)
        val noRelease = Asr(0.5, 0.5, 0.0, 0.8)
        assertEquals(0.8, noRelease.sample(0.999), 0.0)
        assertEquals(0.0, noRelease.sample(1.0), 0.0)
        assertEquals(0.0, noRelease.sample(-0.1), 0.0)
        assertEquals(0.0, Asr(0.0, 0.0, 0.0).length, 0.0)
    }

    @Test
    fun adsr_keys_rampToPeakThenDecayToLevel() {
        val adsr = Adsr(attack = 1.0, decay = 1.0, sustain = 1.0, release = 1.0, peak = 1.0, level = 0.3)
        assertEquals(4.0, adsr.length, 0.0)
        assertEquals(0.5, adsr.sample(0.5), tolerance)
        assertEquals(0.65, adsr.sample(1.5), tolerance)
        assertEquals(0.3, adsr.sample(2.5), tolerance)
        assertEquals(0.15, adsr.sample(3.5), tolerance)
    }

    @Test
    fun repeater_overlappingEnvelopes_combineByMaxOrSumAsAsked() {
        // Stroke's shape: 3 s envelope every 2.6 s; at 2.8 s release 0.06 meets attack 0.06.
        val stroke = Asr(1.0, 1.0, 1.0, 0.3)
        val max = Repeater(stroke, 4, 2.6, Overlap.MAX)
        val sum = Repeater(stroke, 4, 2.6, Overlap.SUM)
        assertEquals(10.8, max.length, tolerance)
        assertEquals(0.06, max.sample(2.8), tolerance)
        assertEquals(0.12, sum.sample(2.8), tolerance)
        assertEquals(0.09, max.sample(2.7), tolerance)
        assertEquals(0.3, max.sample(4.0), tolerance)
    }

    @Test
    fun repeater_sampledAt1000Hz_startsEachRepetitionAtItsPeriodInSamples() {
        // 2.5 ms pulses of 1.0 (no attack, no release), period 10 ms, 3 times: the pulse ends fall
        // between samples, so only the onsets (exactly on samples 10 and 20) are under test.
        val pulses = Repeater(Asr(0.0, 0.0025, 0.0), 3, 0.010, Overlap.MAX)
        val fs = 1000.0
        val onAt = (0 until 30).filter { pulses.sample(it / fs) > 0.5 }
        assertEquals(listOf(0, 1, 2, 10, 11, 12, 20, 21, 22), onAt)
        assertEquals(0.0225, pulses.length, tolerance)
    }

    @Test
    fun sequence_backToBack_playsEachSignalInItsOwnTime() {
        val seq = Sequence(Asr(0.0, 1.0, 0.0, 0.2), Silence(0.5), Asr(1.0, 0.0, 0.0, 0.6))
        assertEquals(2.5, seq.length, 0.0)
        assertEquals(0.2, seq.sample(0.0), 0.0)
        assertEquals(0.0, seq.sample(1.2), 0.0)
        // 0.5 s into the third signal's 1 s attack to 0.6.
        assertEquals(0.3, seq.sample(2.0), tolerance)
        assertEquals(0.0, seq.sample(2.5), 0.0)
    }

    @Test
    fun sample_nonFiniteTimes_throwIllegalArgument() {
        val signals = listOf(
            Sine(1.0), Triangle(1.0), Square(1.0), Asr(1.0, 1.0, 1.0), Silence(1.0),
            Sine(1.0) * Asr(1.0, 1.0, 1.0), Sine(1.0) + Sine(2.0), Sine(1.0) * 0.5,
            Repeater(Asr(1.0, 1.0, 1.0), 3, 2.0, Overlap.MAX), Sequence(Silence(1.0)),
        )
        for (signal in signals) for (t in listOf(Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY)) {
            try {
                signal.sample(t)
                throw AssertionError("${signal::class.simpleName}.sample($t) did not throw")
            } catch (expected: IllegalArgumentException) {
            }
        }
    }

    @Test
    fun sine_afterThreeHours_keepsPhaseToBigDecimalReference() {
        val f = 440.0 * Math.pow(2.0, (127.0 - 69.0) / 12.0)
        val t = 3 * 3600.0 + 0.123456789
        val reference = java.math.BigDecimal(f).multiply(java.math.BigDecimal(t))
            .remainder(java.math.BigDecimal.ONE).toDouble()
        val cycles = Phase.cyclesAt(f, t)
        // The naive f · t keeps only ~1e-8 cycles of fraction at 1.35e8 cycles.
        assertEquals(reference, cycles, 1e-11)
        assertEquals(sin(2 * PI * reference), Sine(f).sample(t), 1e-10)
    }

    @Test
    fun cyclesAt_negativeTime_isStillInZeroToOne() {
        assertEquals(0.75, Phase.cyclesAt(1.0, -0.25), tolerance)
        assertEquals(0.5, SampleClock(1.0, 4).cyclesAt(-2), tolerance)
    }
}
