package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException
import org.hapticon.core.signal.SampleClock
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import kotlin.math.abs

class RendererExtremesTest {
    /** 64 repetitions, exactly 30 s: 63 · 0.4375 + 3 · 0.8125 = 27.5625 + 2.4375 (all exact in binary). */
    private val longest = HapticIcon.LONGEST_ALLOWED

    private fun expectInvalid(field: String, block: () -> Unit) {
        try {
            block()
            fail("expected IconValidationException for $field")
        } catch (e: IconValidationException) {
            assertEquals(field, e.field)
        }
    }

    @Test
    fun sampleCount_zeroDurationIcon_isZeroAndStreamEndsImmediately() {
        val silent = HapticIcon("silent", 0.0, 0.0, 0.5, 0.0, 60.0)
        for (model in EnvelopeModel.values()) for (mode in RenderMode.values()) {
            val renderer = IconRenderer(silent, 48_000, model, mode)
            assertEquals(0L, renderer.sampleCount)
            val stream = renderer.stream()
            assertEquals(0L, stream.totalSamples)
            assertEquals(-1, stream.read(FloatArray(16)))
            assertEquals(0, PcmRenderer(silent, 48_000, model, mode).toShortArray().size)
        }
    }

    @Test
    fun sampleCount_subSampleDurations_roundHalfUp() {
        // At 8 kHz one sample is 125 µs: 0.4 sample → 0, 0.5 → 1, 1.6 → 2.
        assertEquals(0L, IconRenderer(HapticIcon("a", 0.00005, 0.0, 1.0, 0.0, 60.0), 8_000).sampleCount)
        assertEquals(1L, IconRenderer(HapticIcon("b", 0.0000625, 0.0, 1.0, 0.0, 60.0), 8_000).sampleCount)
        assertEquals(2L, IconRenderer(HapticIcon("c", 0.0002, 0.0, 1.0, 0.0, 60.0), 8_000).sampleCount)
    }

    @Test
    fun envelopeAt_subSampleAttack_paperSamplesTheRampProcessingLastsOneSample() {
        // attack 0.3 sample at 8 kHz, then 1 ms sustain at 0.8.
        val icon = HapticIcon("tiny", 0.3 / 8_000, 0.001, 0.8, 0.0, 60.0)
        assertEquals(0.0, IconRenderer(icon, 8_000, EnvelopeModel.PAPER).envelopeAt(0), 0.0)
        assertEquals(0.8, IconRenderer(icon, 8_000, EnvelopeModel.PAPER).envelopeAt(1), 0.0)
        // PROCESSING: JSyn clamps a duration under one frame period to one sample: sample 0 outputs the
        // reader's start (0), sample 1 starts the sustain at the attack target 1.
        val processing = IconRenderer(icon, 8_000, EnvelopeModel.PROCESSING)
        assertEquals(0.0, processing.envelopeAt(0), 0.0)
        assertEquals(1.0, processing.envelopeAt(1), 1e-12)
    }

    @Test
    fun constructor_note127At44100_isAcceptedAndRendersIts12543HzCarrier() {
        val icon = HapticIcon("high", 0.0, 0.01, 1.0, 0.0, 127.0)
        val renderer = IconRenderer(icon, 44_100, EnvelopeModel.PAPER)
        assertEquals(12_543.853951415975, icon.frequency, 1e-9)
        for (i in listOf(1L, 2L, 200L, 440L)) {
            assertEquals(IconReference.sample(icon, EnvelopeModel.PAPER, i, 44_100), renderer.sampleAt(i), 1e-12)
        }
    }

    @Test
    fun constructor_note127At8000_throwsForNote() {
        expectInvalid("note") { IconRenderer(HapticIcon("high", 0.0, 0.01, 1.0, 0.0, 127.0), 8_000) }
    }

    @Test
    fun constructor_carrierExactlyAtNyquist_throwsForNoteButOneHertzAboveIsFine() {
        // note 117 = 440 · 2^4 = 7040 Hz exactly = Nyquist of 14080 Hz.
        val icon = HapticIcon("nyquist", 0.0, 0.01, 1.0, 0.0, 117.0)
        expectInvalid("note") { IconRenderer(icon, 14_080) }
        assertEquals(141L, IconRenderer(icon, 14_081).sampleCount)
    }

    @Test
    fun constructor_ratesOutsideRange_throwForSampleRate() {
        expectInvalid("sampleRate") { IconRenderer(HapticIcon.HIT, 7_999) }
        expectInvalid("sampleRate") { IconRenderer(HapticIcon.HIT, 192_001) }
        expectInvalid("sampleRate") { PcmRenderer(HapticIcon.HIT, 7_999) }
    }

    @Test
    fun sampleAt_note0At8000And192000_matchesReference() {
        val icon = HapticIcon("low", 0.1, 0.1, 0.9, 0.1, 0.0)
        for (fs in listOf(8_000, 192_000)) for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(icon, fs, model)
            assertEquals(Math.round(0.3 * fs), renderer.sampleCount)
            for (i in listOf(1L, fs / 20L, fs / 10L, fs / 5L, renderer.sampleCount - 1)) {
                assertEquals("$fs $model $i", IconReference.sample(icon, model, i, fs), renderer.sampleAt(i), 1e-12)
            }
        }
    }

    @Test
    fun longestAllowed_isExactlyAtBothSafetyCaps() {
        assertEquals(HapticIcon.MAX_DURATION_SECONDS, longest.duration, 0.0)
        assertEquals(HapticIcon.MAX_COUNT, longest.count)
        assertEquals(1_323_000L, IconRenderer(longest, 44_100).sampleCount)
        expectInvalid("duration") { longest.copy(sustain = longest.sustain + 1e-6) }
        expectInvalid("count") { longest.copy(count = HapticIcon.MAX_COUNT + 1, period = 0.1) }
    }

    @Test
    fun constructor_iconsAboveTheCap_areRejected() {
        expectInvalid("count") { HapticIcon("many", 0.01, 0.0, 1.0, 0.01, 60.0, 0.1, 65) }
        expectInvalid("duration") { HapticIcon("long", 0.8125, 0.8125, 0.7, 0.8125, 69.0, 0.4376, 64) }
    }

    @Test
    fun sampleAt_longestIconAt192000_hasThirtySecondsAndExactPhaseAtTheEnd() {
        val renderer = IconRenderer(longest, 192_000, EnvelopeModel.PAPER)
        assertEquals(5_760_000L, renderer.sampleCount)
        for (i in listOf(5_759_999L, 5_000_001L, 2_880_000L)) {
            assertEquals("sample $i", IconReference.sample(longest, EnvelopeModel.PAPER, i, 192_000), renderer.sampleAt(i), 1e-11)
        }
    }

    @Test
    fun cyclesAt_thirtySecondsAt192000_driftsLessThan1e9Cycles() {
        for (note in listOf(0.0, 57.0, 100.0, 127.0)) {
            val f = 440.0 * Math.pow(2.0, (note - 69.0) / 12.0)
            val clock = SampleClock(f, 192_000)
            var worst = 0.0
            for (i in listOf(5_759_999L, 5_759_000L, 3_000_017L, 191_999L, 192_000L)) {
                val error = abs(clock.cyclesAt(i) - IconReference.cycles(f, i, 192_000))
                worst = maxOf(worst, minOf(error, 1.0 - error))
            }
            assertTrue("note $note drift $worst", worst < 1e-9)
        }
    }

    @Test
    fun sampleAt_outOfRange_throwsIndexOutOfBounds() {
        val renderer = IconRenderer(HapticIcon.KNOCK, 48_000)
        for (index in listOf(-1L, renderer.sampleCount)) {
            try {
                renderer.sampleAt(index)
                fail("sampleAt($index)")
            } catch (expected: IndexOutOfBoundsException) {
            }
            try {
                renderer.envelopeAt(index)
                fail("envelopeAt($index)")
            } catch (expected: IndexOutOfBoundsException) {
            }
        }
    }
}
