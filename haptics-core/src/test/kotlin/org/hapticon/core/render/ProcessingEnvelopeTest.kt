package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel.PAPER
import org.hapticon.core.render.EnvelopeModel.PROCESSING
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test

/** The Processing Sound 2.0.1–2.3.1 + JSyn rules of [ProcessingEnvelope], at 44.1 and 48 kHz. */
class ProcessingEnvelopeTest {
    private fun segmentEnds(icon: HapticIcon, fs: Int) = ProcessingEnvelope.segments(icon, fs).map { it.endSample }

    @Test
    fun segments_presets_endWhereTheReadersRunningPhaseFirstReachesOne() {
        // Independently simulated (a Python transliteration of VariableRateMonoReader.generate).
        assertEquals(listOf(44_100L, 88_200L, 132_300L), segmentEnds(HapticIcon.STROKE, 44_100))
        assertEquals(listOf(441L, 4_851L, 6_174L), segmentEnds(HapticIcon.HIT, 44_100))
        // knock: 220.5-sample attack ends at 221; its overshoot shortens the sustain to end at 661, not 662.
        assertEquals(listOf(221L, 661L, 882L), segmentEnds(HapticIcon.KNOCK, 44_100))
        assertEquals(listOf(66_150L, 110_250L, 132_300L), segmentEnds(HapticIcon.HUG, 44_100))
        assertEquals(listOf(48_000L, 96_000L, 144_000L), segmentEnds(HapticIcon.STROKE, 48_000))
        assertEquals(listOf(480L, 5_280L, 6_720L), segmentEnds(HapticIcon.HIT, 48_000))
        assertEquals(listOf(240L, 720L, 960L), segmentEnds(HapticIcon.KNOCK, 48_000))
        // hug at 48 kHz: 72000 additions of 1/72000 fall short of 1, so the attack lasts one sample more;
        // the release then runs into the disconnection at 3.0 s = sample 144000, which cuts it.
        assertEquals(listOf(72_001L, 120_001L, 144_000L), segmentEnds(HapticIcon.HUG, 48_000))
    }

    @Test
    fun segments_subSampleDurations_lastExactlyOneSampleEach() {
        // 10 µs attack and release at 44.1 kHz (0.44 samples): each lasts one sample.
        val icon = HapticIcon("blip", 0.00001, 0.01, 0.5, 0.00001, 60.0)
        val segments = ProcessingEnvelope.segments(icon, 44_100)
        assertEquals(1L, segments[0].endSample)
        assertEquals(442L, segments[1].endSample) // 0.01f s = 441 samples of sustain after the one-sample attack
        // A+S+R = 0.01002 s = 441.88 samples: the disconnection waits for the block start at 448 (= 8 · 56),
        // so the one-sample release still plays.
        assertEquals(448L, ProcessingEnvelope.disconnectSample(icon, 44_100))
        assertEquals(443L, segments[2].endSample)
        val renderer = IconRenderer(icon, 44_100, PROCESSING)
        assertEquals(0.0, renderer.envelopeAt(0), 0.0) // the starved reader's first sample
        assertEquals(1.0, renderer.envelopeAt(1), 1e-12) // the attack target, reached after one sample
    }

    @Test
    fun disconnectSample_presets_waitForTheFirstEightFrameBlockStartAtOrAfterTheStamp() {
        // ceil((A+S+R)·fs) rounded up to JSyn's 8-frame blocks.
        assertEquals(132_304L, ProcessingEnvelope.disconnectSample(HapticIcon.STROKE, 44_100)) // 132 300 is not a block start
        assertEquals(144_000L, ProcessingEnvelope.disconnectSample(HapticIcon.STROKE, 48_000)) // 3.0 s is one exactly
        assertEquals(6_176L, ProcessingEnvelope.disconnectSample(HapticIcon.HIT, 44_100)) // 0.14000000059604645 s = 6174.00003 samples
        assertEquals(6_728L, ProcessingEnvelope.disconnectSample(HapticIcon.HIT, 48_000)) // 6720.0000286 samples: past 6720
        assertEquals(888L, ProcessingEnvelope.disconnectSample(HapticIcon.KNOCK, 44_100))
        assertEquals(960L, ProcessingEnvelope.disconnectSample(HapticIcon.KNOCK, 48_000)) // 0.02f s = 959.99998 samples
        assertEquals(144_000L, ProcessingEnvelope.disconnectSample(HapticIcon.HUG, 48_000))
        // A block multiple whose time compares at or after the stamp, and one block earlier does not.
        for (icon in HapticIcon.PRESETS) for (fs in listOf(8_000, 44_100, 48_000, 96_000)) {
            val n = ProcessingEnvelope.disconnectSample(icon, fs)
            val stamp = (icon.attack.toFloat() + icon.sustain.toFloat() + icon.release.toFloat()).toDouble()
            assertEquals(0L, n % ProcessingEnvelope.FRAMES_PER_BLOCK)
            assertTrue("${icon.name} $fs", n * (1.0 / fs) >= stamp && (n - 8) * (1.0 / fs) < stamp)
        }
    }

    @Test
    fun segments_allDurationsUnderOneSample_playOneSampleEachBeforeTheBlockStartDisconnects() {
        // A+S+R = 30 µs = 1.32 samples, but the disconnection waits for the next block start, sample 8: the
        // reader plays its three one-sample segments.
        val icon = HapticIcon("tick", 0.00001, 0.00001, 0.8, 0.00001, 60.0)
        assertEquals(8L, ProcessingEnvelope.disconnectSample(icon, 44_100))
        assertEquals(listOf(1L, 2L, 3L), segmentEnds(icon, 44_100))
        val renderer = IconRenderer(icon, 44_100, PROCESSING)
        assertEquals(1L, renderer.sampleCount) // round(30 µs · fs): only the starved first sample is rendered
        assertEquals(0.0, renderer.envelopeAt(0), 0.0)
    }

    @Test
    fun envelopeAt_strokeRetriggeredMidRelease_addsBothReaders() {
        // Stroke: a 3.0 s envelope every 2.6 s. Repetition 1 starts 0.6 s into repetition 0's 1 s release.
        val level = 0.3f.toDouble()
        for (fs in listOf(44_100, 48_000)) {
            val processing = IconRenderer(HapticIcon.STROKE, fs, PROCESSING)
            val paper = IconRenderer(HapticIcon.STROKE, fs, PAPER)
            val onset = Math.round(2.6 * fs)
            val step = (1.0 / fs) * (1.0 / 1.0f.toDouble())
            val release = level * (1.0 - 0.6) // repetition 0 at its onset + 2.6 s
            assertEquals("$fs onset", release, processing.envelopeAt(onset), 1e-9)
            // 1000 samples later: both readers move, the release down and the attack up.
            val m = 1_000L
            val expected = level * (1.0 - 0.6 - m * step) + m * step
            assertEquals("$fs onset + $m", expected, processing.envelopeAt(onset + m), 1e-9)
            // PAPER keeps the larger one (here the release).
            assertEquals("$fs paper", 0.3 * (1.0 - 0.6 - m * step), paper.envelopeAt(onset + m), 1e-12)
            // At 3.0 s repetition 0 is disconnected: repetition 1 alone, 0.4 s into its attack.
            val end = Math.round(3.0 * fs)
            assertEquals("$fs 3.0 s", 0.4, processing.envelopeAt(end), 1e-9)
            assertEquals("$fs just before 3.0 s", 0.4 - step + level * step, processing.envelopeAt(end - 1), 1e-9)
        }
    }

    @Test
    fun envelopeAt_strokeOverlapWindow_sumExceedsTheMaximumByUpToTheSmallerReader() {
        // Over 2.6..3.0 s the sum and the maximum differ by the smaller reader: largest at 2.6 + 0.3·0.4/1.3 s.
        val fs = 44_100
        val sum = IconRenderer(HapticIcon.STROKE, fs, PROCESSING)
        var largest = 0.0
        var at = 0L
        for (i in Math.round(2.6 * fs) until Math.round(3.0 * fs)) {
            val n = i - Math.round(2.6 * fs)
            val t = n / fs.toDouble()
            val release = 0.3f.toDouble() * (0.4 - t)
            val attack = t
            val difference = sum.envelopeAt(i) - maxOf(release, attack)
            if (difference > largest) { largest = difference; at = i }
        }
        // The readers cross where 0.3·(0.4 − t) = t, t = 0.0923 s: the sum is 0.092 above the maximum there.
        assertEquals(0.0923, largest, 1e-3)
        assertEquals(Math.round((2.6 + 0.12 / 1.3) * fs).toDouble(), at.toDouble(), 1.0)
    }

    @Test
    fun segments_levelAndDurations_passThroughFloatAsEnvPlaysParametersDo() {
        val segments = ProcessingEnvelope.segments(HapticIcon.STROKE, 44_100)
        // The sustain ramps 1 → 0.3f (0.30000001192092896), not to 0.3.
        assertEquals(0.3f.toDouble() - 1.0, segments[1].slope * 44_100, 1e-9)
        assertEquals(0.30000001192092896, 0.3f.toDouble(), 0.0)
    }

    @Test
    fun outputs_summedEnvelopeAboveOne_areClippedToFullScaleAndTheVibratorCap() {
        // Six overlapping 2.4375 s envelopes every 0.4375 s add far above 1, as JSyn's mixer would before the DAC.
        val icon = HapticIcon.LONGEST_ALLOWED
        val renderer = IconRenderer(icon, 8_000, PROCESSING)
        val peak = (0 until renderer.sampleCount).maxOf { renderer.envelopeAt(it) }
        assertEquals(3.2, peak, 0.1)
        val pcm = PcmRenderer(icon, 8_000, PROCESSING).toShortArray()
        assertEquals(32_767, pcm.maxOf { it.toInt() })
        assertEquals(-32_767, pcm.minOf { it.toInt() })
        val waveform = VibrationWaveform.amplitudeSteps(icon, PROCESSING)
        assertEquals(VibrationWaveform.MAX_AMPLITUDE, waveform.amplitudes().max())
    }
}
