package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel.PAPER
import org.hapticon.core.render.EnvelopeModel.PROCESSING
import org.junit.Assert.assertEquals
import org.junit.Test
import kotlin.math.PI
import kotlin.math.sin

class IconRendererPresetTest {
    private val tolerance = 1e-12

    @Test
    fun sampleCount_presetsAt44100And48000_isRoundedDurationTimesRateInBothModels() {
        val expected = mapOf(
            // duration (count − 1)·period + A + S + R: stroke 10.8 s, hit 1.54 s, knock 0.56 s, hug 3.0 s
            "stroke" to Pair(476_280L, 518_400L),
            "hit" to Pair(67_914L, 73_920L),
            "knock" to Pair(24_696L, 26_880L),
            "hug" to Pair(132_300L, 144_000L),
        )
        for (icon in HapticIcon.PRESETS) for (model in EnvelopeModel.values()) {
            assertEquals("${icon.name} $model 44.1k", expected.getValue(icon.name).first, IconRenderer(icon, 44_100, model).sampleCount)
            assertEquals("${icon.name} $model 48k", expected.getValue(icon.name).second, IconRenderer(icon, 48_000, model).sampleCount)
        }
    }

    @Test
    fun sampleAt_everyPresetBothModelsAtNamedIndices_matchesIndependentFormula() {
        for (fs in listOf(44_100, 48_000)) for (icon in HapticIcon.PRESETS) for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(icon, fs, model)
            for ((name, index) in presetNamedIndices(icon, model, fs)) {
                val label = "${icon.name} $model $fs Hz, $name (sample $index)"
                assertEquals(label, IconReference.sample(icon, model, index, fs), renderer.sampleAt(index), tolerance)
                assertEquals(label, IconReference.envelope(icon, model, index, fs), renderer.envelopeAt(index), tolerance)
            }
        }
    }

    @Test
    fun sampleAt_everySampleOfEveryPresetAt8000_matchesIndependentFormula() {
        for (icon in HapticIcon.PRESETS) for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(icon, 8_000, model)
            for (i in 0 until renderer.sampleCount) {
                assertEquals("${icon.name} $model sample $i", IconReference.sample(icon, model, i, 8_000), renderer.sampleAt(i), tolerance)
            }
        }
    }

    @Test
    fun envelopeAt_sixtyFourHeavilyOverlappingRepetitions_isTheMaximumOverAllOfThem() {
        // Each envelope lasts 2.4375 s and a new one starts every 0.4375 s: up to 6 overlap.
        val longest = HapticIcon.LONGEST_ALLOWED
        for (fs in listOf(8_000, 44_100)) for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(longest, fs, model)
            for (i in 0 until renderer.sampleCount step 3) {
                assertEquals("$fs $model $i", IconReference.envelope(longest, model, i, fs), renderer.envelopeAt(i), tolerance)
            }
        }
    }

    @Test
    fun sampleAt_paperModel_isLevelTimesSineOfContinuousPhase() {
        // hug, 48 kHz, mid-sustain sample 96000 (t = 2.0 s): level 0.5 times a 146.83 Hz sine at t = 2 s.
        val hug = IconRenderer(HapticIcon.HUG, 48_000, PAPER)
        val f = 440.0 * Math.pow(2.0, (50.0 - 69.0) / 12.0)
        assertEquals(0.5, hug.envelopeAt(96_000), 0.0)
        assertEquals(0.5 * sin(2.0 * PI * (f * 2.0 - 293.0)), hug.sampleAt(96_000), tolerance)
        assertEquals(0.0, hug.sampleAt(0), 0.0)
    }

    @Test
    fun envelopeAt_strokeOverlapAt2point8s_isMaximumOfReleaseAndNextAttack() {
        // Stroke: rep 0 releases 0.3 → 0 over [2.0, 3.0) s, rep 1 attacks from 2.6 s.
        for (fs in listOf(44_100, 48_000)) {
            val i = Math.round(2.8 * fs)
            val i27 = Math.round(2.7 * fs)
            val paper = IconRenderer(HapticIcon.STROKE, fs, PAPER)
            // PAPER at 2.8 s: release 0.3·0.2 = 0.06 = attack 0.3·0.2 (a sum would give 0.12).
            assertEquals(0.06, paper.envelopeAt(i), tolerance)
            // at 2.7 s: release 0.09 beats attack 0.03.
            assertEquals(0.09, paper.envelopeAt(i27), tolerance)
            val processing = IconRenderer(HapticIcon.STROKE, fs, PROCESSING)
            // PROCESSING at 2.8 s: release 0.3·0.2 = 0.06 loses to attack 0→1 at 0.2 s = 0.2.
            assertEquals(0.2, processing.envelopeAt(i), tolerance)
            // at 2.7 s: release 0.09 is still below attack 0.1.
            assertEquals(0.1, processing.envelopeAt(i27), tolerance)
        }
    }

    @Test
    fun envelopeAt_repetitionK_startsAtSampleKTimesPeriod() {
        // hit at 48 kHz: period 0.2 s = 9600 samples, attack 0.01 s = 480 samples, one envelope 6720 samples;
        // its level is 1, so both models ramp 0 → 1 over the attack.
        for (model in EnvelopeModel.values()) {
            val hit = IconRenderer(HapticIcon.HIT, 48_000, model)
            for (k in 1 until 8) {
                val onset = 9_600L * k
                assertEquals("$model k=$k before", 0.0, hit.envelopeAt(onset - 1), 0.0)
                assertEquals("$model k=$k onset", 0.0, hit.envelopeAt(onset), 0.0)
                assertEquals("$model k=$k onset+1", 1.0 / 480.0, hit.envelopeAt(onset + 1), tolerance)
            }
        }
    }

    @Test
    fun envelopeAt_onsetBetweenSamples_startsOnTheNearestSample() {
        // period 0.0125 s at 44.1 kHz is 551.25 samples: repetition 1 starts at sample 551, and its
        // 441-sample attack is measured from there (not from 551.25).
        val icon = HapticIcon("offgrid", 0.01, 0.0, 0.8, 0.0, 60.0, 0.0125, 2)
        for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(icon, 44_100, model)
            assertEquals(992L, renderer.sampleCount)
            assertEquals("$model", 0.0, renderer.envelopeAt(550), 0.0)
            assertEquals("$model", 0.0, renderer.envelopeAt(551), 0.0)
            val peak = if (model == PAPER) 0.8 else 1.0
            assertEquals("$model", peak * 1.0 / 441.0, renderer.envelopeAt(552), tolerance)
            assertEquals("$model", peak * 440.0 / 441.0, renderer.envelopeAt(991), tolerance)
        }
    }

    @Test
    fun envelopeAt_zeroAttack_startsAtLevelOnEveryRepetition() {
        val icon = HapticIcon("step", 0.0, 0.01, 0.5, 0.01, 60.0, 0.05, 3)
        val paper = IconRenderer(icon, 48_000, PAPER)
        for (onset in listOf(0L, 2_400L, 4_800L)) {
            assertEquals("onset $onset", 0.5, paper.envelopeAt(onset), 0.0)
            if (onset > 0) assertEquals("before $onset", 0.0, paper.envelopeAt(onset - 1), 0.0)
        }
        // PROCESSING without an attack starts at the attack target 1 and ramps to the level over the sustain.
        val processing = IconRenderer(icon, 48_000, PROCESSING)
        assertEquals(1.0, processing.envelopeAt(0), 0.0)
        assertEquals(1.0 - 0.5 * 240.0 / 480.0, processing.envelopeAt(240), tolerance)
        assertEquals(0.5, processing.envelopeAt(480), 0.0)
    }

    @Test
    fun sampleAt_processingCarrier_advancesPhaseBeforeTheFirstSample() {
        // With no attack the PROCESSING envelope is 1 at sample 0, exposing the carrier: sin(π · 2f/fs).
        val icon = HapticIcon("probe", 0.0, 0.01, 0.5, 0.01, 69.0)
        val renderer = IconRenderer(icon, 48_000, PROCESSING)
        assertEquals(sin(PI * 2.0 * 440.0 / 48_000), renderer.sampleAt(0), tolerance)
        // sample 1: the envelope has ramped 1/480 of the way from 1 to 0.5; phase advanced twice.
        assertEquals((1.0 - 0.5 / 480.0) * sin(PI * 2.0 * 440.0 * 2 / 48_000), renderer.sampleAt(1), tolerance)
    }

    @Test
    fun envelopeAt_processingKnockAt44100_roundsCumulativeBoundariesHalfUp() {
        // knock: A 0.005 s = 220.5 samples → attack is samples 0..220 (round half up: 221 samples),
        // A+S 0.015 s = 661.5 → sustain 221..661, A+S+R 0.02 s = 882 → release 662..881.
        val knock = IconRenderer(HapticIcon.KNOCK, 44_100, PROCESSING)
        assertEquals(220.0 / 220.5, knock.envelopeAt(220), tolerance)
        assertEquals(1.0, knock.envelopeAt(221), 0.0)
        assertEquals(1.0 - 0.5 * 440.0 / 441.0, knock.envelopeAt(661), tolerance)
        assertEquals(0.5, knock.envelopeAt(662), 0.0)
        assertEquals(0.5 - 0.5 * 219.0 / 220.5, knock.envelopeAt(881), tolerance)
        assertEquals(0.0, knock.envelopeAt(882), 0.0)
        assertEquals(0.0, knock.envelopeAt(11_906), 0.0)
        assertEquals(0.0, knock.envelopeAt(11_907), 0.0)
        assertEquals(1.0 / 220.5, knock.envelopeAt(11_908), tolerance)
    }

    @Test
    fun pcm_everyPresetBothModelsAt48000_matchesExpectedIntegersAtNamedIndices() {
        // Expected values from the independent reference formula, rounded half away from zero.
        val expected: Map<Pair<String, EnvelopeModel>, List<Pair<Long, Int>>> = mapOf(
            ("stroke" to PAPER) to listOf(0L to 0, 1L to 0, 47_999L to 9667, 48_000L to 9738, 72_000L to -8221,
                96_000L to 2656, 518_399L to 0, 124_800L to -163, 134_400L to -1666),
            ("stroke" to PROCESSING) to listOf(0L to 0, 1L to 0, 47_999L to 32460, 48_000L to 32631, 72_000L to -17261,
                96_000L to 2220, 518_399L to 0, 124_800L to 17, 134_400L to -5389),
            ("hit" to PAPER) to listOf(0L to 0, 1L to 2, 479L to 30795, 480L to 31163, 2_880L to 31163,
                5_280L to 31163, 73_919L to -22, 9_600L to 0),
            ("hit" to PROCESSING) to listOf(0L to 0, 1L to 4, 479L to 31098, 480L to 31442, 2_880L to 31442,
                5_280L to 31442, 73_919L to -22, 9_600L to 0),
            ("knock" to PAPER) to listOf(0L to 0, 1L to 2, 239L to 9206, 240L to 9630, 480L to 15582,
                720L to 15582, 26_879L to 64, 12_960L to 0),
            ("knock" to PROCESSING) to listOf(0L to 0, 1L to 8, 239L to 19180, 240L to 20015, 480L to 23581,
                720L to 15429, 26_879L to 65, 12_960L to 0),
            ("hug" to PAPER) to listOf(0L to 0, 1L to 0, 71_999L to 16377, 72_000L to 16383, 96_000L to -14090,
                120_000L to 7979, 143_999L to 0),
            ("hug" to PROCESSING) to listOf(0L to 0, 1L to 0, 71_999L to 32765, 72_000L to 32765, 96_000L to -21372,
                120_000L to 8253, 143_999L to 0),
        )
        for (icon in HapticIcon.PRESETS) for (model in EnvelopeModel.values()) {
            val pcm = PcmRenderer(icon, 48_000, model).render()
            for ((index, value) in expected.getValue(icon.name to model)) {
                assertEquals("${icon.name} $model sample $index", value, pcm[index.toInt()].toInt())
                assertEquals("${icon.name} $model reference $index", value, IconReference.pcm(IconReference.sample(icon, model, index, 48_000)))
            }
        }
    }
}
