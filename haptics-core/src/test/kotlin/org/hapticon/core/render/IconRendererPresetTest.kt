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

    /**
     * PROCESSING values agree with the transliterated JSyn reader to this: the reader sums its phase sample by
     * sample, the renderer evaluates phase₀ + m · increment (segment boundaries are found by the same sum, so
     * they agree exactly).
     */
    private val runningSumTolerance = 1e-10

    private fun toleranceOf(model: EnvelopeModel) = if (model == PROCESSING) runningSumTolerance else tolerance

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
                assertEquals(label, IconReference.sample(icon, model, index, fs), renderer.sampleAt(index), toleranceOf(model))
                assertEquals(label, IconReference.envelope(icon, model, index, fs), renderer.envelopeAt(index), toleranceOf(model))
            }
        }
    }

    @Test
    fun sampleAt_everySampleOfEveryPresetAt8000_matchesIndependentFormula() {
        for (icon in HapticIcon.PRESETS) for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(icon, 8_000, model)
            for (i in 0 until renderer.sampleCount) {
                assertEquals("${icon.name} $model sample $i", IconReference.sample(icon, model, i, 8_000), renderer.sampleAt(i), toleranceOf(model))
            }
        }
    }

    @Test
    fun envelopeAt_sixtyFourHeavilyOverlappingRepetitions_combinesAllOfThemPerModel() {
        // Each envelope lasts 2.4375 s and a new one starts every 0.4375 s: up to 6 overlap.
        val longest = HapticIcon.LONGEST_ALLOWED
        for (fs in listOf(8_000, 44_100)) for (model in EnvelopeModel.values()) {
            val renderer = IconRenderer(longest, fs, model)
            for (i in 0 until renderer.sampleCount step 3) {
                assertEquals("$fs $model $i", IconReference.envelope(longest, model, i, fs), renderer.envelopeAt(i), toleranceOf(model))
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
    fun envelopeAt_strokeOverlapAt2point8s_paperTakesTheMaximumProcessingTheSum() {
        // Stroke: rep 0 releases 0.3 → 0 over [2.0, 3.0) s, rep 1 attacks from 2.6 s.
        val level = 0.3f.toDouble() // Env.play takes the level as a float
        for (fs in listOf(44_100, 48_000)) {
            val i = Math.round(2.8 * fs)
            val i27 = Math.round(2.7 * fs)
            val paper = IconRenderer(HapticIcon.STROKE, fs, PAPER)
            // PAPER at 2.8 s: release 0.3·0.2 = 0.06 = attack 0.3·0.2 (a sum would give 0.12).
            assertEquals(0.06, paper.envelopeAt(i), tolerance)
            // at 2.7 s: release 0.09 beats attack 0.03.
            assertEquals(0.09, paper.envelopeAt(i27), tolerance)
            val processing = IconRenderer(HapticIcon.STROKE, fs, PROCESSING)
            // PROCESSING adds both readers (InputMixingBlockPart): release 0.3·0.2 + attack 0→1 at 0.2 s.
            assertEquals("$fs", level * 0.2 + 0.2, processing.envelopeAt(i), runningSumTolerance)
            // at 2.7 s: release 0.3·0.3 + attack 0.1 (the maximum would be 0.1).
            assertEquals("$fs", level * 0.3 + 0.1, processing.envelopeAt(i27), runningSumTolerance)
        }
    }

    @Test
    fun envelopeAt_repetitionK_startsAtSampleKTimesPeriod() {
        // hit at 48 kHz: period 0.2 s = 9600 samples, attack 0.01 s = 480 samples, one envelope 6720 samples;
        // its level is 1, so both models ramp 0 → 1 over the attack (PROCESSING over the float 0.01f s).
        for (model in EnvelopeModel.values()) {
            val hit = IconRenderer(HapticIcon.HIT, 48_000, model)
            val step = if (model == PAPER) 1.0 / 480.0 else (1.0 / 48_000) * (1.0 / 0.01f.toDouble())
            for (k in 1 until 8) {
                val onset = 9_600L * k
                assertEquals("$model k=$k before", 0.0, hit.envelopeAt(onset - 1), 0.0)
                assertEquals("$model k=$k onset", 0.0, hit.envelopeAt(onset), 0.0)
                assertEquals("$model k=$k onset+1", step, hit.envelopeAt(onset + 1), tolerance)
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
            val step = if (model == PAPER) 0.8 / 441.0 else (1.0 / 44_100) * (1.0 / 0.01f.toDouble())
            assertEquals("$model", step, renderer.envelopeAt(552), tolerance)
            assertEquals("$model", step * 440.0, renderer.envelopeAt(991), toleranceOf(model))
        }
    }

    @Test
    fun envelopeAt_zeroAttack_paperStartsAtLevelProcessingRisesForOneSample() {
        val icon = HapticIcon("step", 0.0, 0.01, 0.5, 0.01, 60.0, 0.05, 3)
        val paper = IconRenderer(icon, 48_000, PAPER)
        for (onset in listOf(0L, 2_400L, 4_800L)) {
            assertEquals("onset $onset", 0.5, paper.envelopeAt(onset), 0.0)
            if (onset > 0) assertEquals("before $onset", 0.0, paper.envelopeAt(onset - 1), 0.0)
        }
        // PROCESSING: a 0 s attack lasts one sample (SegmentedEnvelope.getRateScaler clamps it to the frame
        // period): 0 at the onset, the attack target 1 one sample later, then the sustain ramps to 0.5 over
        // 480 samples and the release to 0; the reader is disconnected at ceil(0.02f · 48000) = 960.
        val processing = IconRenderer(icon, 48_000, PROCESSING)
        for (onset in listOf(0L, 2_400L, 4_800L)) {
            assertEquals("onset $onset", 0.0, processing.envelopeAt(onset), 0.0)
            assertEquals("onset $onset + 1", 1.0, processing.envelopeAt(onset + 1), tolerance)
            assertEquals("onset $onset + 241", 0.75, processing.envelopeAt(onset + 241), 1e-8)
            assertEquals("onset $onset + 481", 0.5, processing.envelopeAt(onset + 481), 1e-7)
            // 478 of the 480 release samples: 0.5 · 2/480; the reader would still output 0.5/480 at 960, but it is disconnected.
            assertEquals("onset $onset + 959", 1.0 / 480, processing.envelopeAt(onset + 959), 1e-7)
            if (onset + 960 < processing.sampleCount) assertEquals("onset $onset + 960", 0.0, processing.envelopeAt(onset + 960), 0.0)
        }
    }

    @Test
    fun sampleAt_processingCarrier_advancesPhaseBeforeEachSample() {
        // With no attack the PROCESSING envelope is 1 at sample 1, exposing the carrier: phase (1 + 1) · f/fs.
        val icon = HapticIcon("probe", 0.0, 0.01, 0.5, 0.01, 69.0)
        val renderer = IconRenderer(icon, 48_000, PROCESSING)
        assertEquals(0.0, renderer.sampleAt(0), 0.0)
        assertEquals(sin(2.0 * PI * 440.0 * 2 / 48_000), renderer.sampleAt(1), tolerance)
    }

    @Test
    fun envelopeAt_processingKnockAt44100_carriesTheAttackOvershootIntoTheSustain() {
        // knock: A 0.005 s = 220.5 samples. The attack phase first reaches 1 at sample 221, overshooting by
        // half an attack sample (0.00227 in phase units). That overshoot is carried into the sustain in
        // phase units, where it is worth one whole 441-sample-sustain sample: the sustain ends at sample 661,
        // not at the time-exact 661.5 → 662. The release then runs to the disconnection at 882.
        val knock = IconRenderer(HapticIcon.KNOCK, 44_100, PROCESSING)
        val framePeriod = 1.0 / 44_100
        val attackStep = framePeriod * (1.0 / 0.005f.toDouble())
        val sustainStep = framePeriod * (1.0 / 0.01f.toDouble())
        val level = 0.5f.toDouble()
        assertEquals(220 * attackStep, knock.envelopeAt(220), tolerance)
        val carry = 221 * attackStep - 1.0
        assertEquals(0.0022675736961, carry, 1e-6)
        assertEquals(1.0 + (level - 1.0) * carry, knock.envelopeAt(221), tolerance)
        assertEquals(1.0 + (level - 1.0) * (carry + 439 * sustainStep), knock.envelopeAt(660), runningSumTolerance)
        // Sample 661 is already the release: source 0.5, phase = the sustain's tiny overshoot.
        assertEquals(level, knock.envelopeAt(661), 1e-7)
        assertEquals(level * (1.0 - 220 * attackStep), knock.envelopeAt(881), 1e-7)
        assertEquals(0.0, knock.envelopeAt(882), 0.0)
        assertEquals(0.0, knock.envelopeAt(11_906), 0.0)
        assertEquals(0.0, knock.envelopeAt(11_907), 0.0)
        assertEquals(attackStep, knock.envelopeAt(11_908), tolerance)
    }

    @Test
    fun envelopeAt_processingHitAt48000_agreesWithTheTimeExactScheduleBecauseFloatsOvershootByNothing() {
        // hit at 48 kHz: 0.01f s is 479.99999 samples, so the attack phase reaches 1 at sample 480 with an
        // overshoot of 2.2e-8, and the sustain (0.1f s) ends at 5280 and the release at 6720, as time-exact.
        val hit = IconRenderer(HapticIcon.HIT, 48_000, PROCESSING)
        val attackStep = (1.0 / 48_000) * (1.0 / 0.01f.toDouble())
        assertEquals(479 * attackStep, hit.envelopeAt(479), runningSumTolerance)
        assertEquals(1.0, hit.envelopeAt(480), 0.0) // level 1: the sustain ramps 1 → 1
        assertEquals(1.0, hit.envelopeAt(5_279), 0.0)
        assertEquals(1.0, hit.envelopeAt(5_280), 1e-7)
        assertEquals(1.0 / 1_440, hit.envelopeAt(6_719), 1e-7)
        assertEquals(0.0, hit.envelopeAt(6_720), 0.0)
    }

    @Test
    fun pcm_everyPresetBothModelsAt48000_matchesExpectedIntegersAtNamedIndices() {
        // Expected values from the independent reference formula, rounded half away from zero. PROCESSING
        // stroke at 134400 (2.8 s) is the sum of two repetitions (-7006; their maximum gave -5389).
        val expected: Map<Pair<String, EnvelopeModel>, List<Pair<Long, Int>>> = mapOf(
            ("stroke" to PAPER) to listOf(0L to 0, 1L to 0, 47_999L to 9667, 48_000L to 9738, 72_000L to -8221,
                96_000L to 2656, 518_399L to 0, 124_800L to -163, 134_400L to -1666),
            ("stroke" to PROCESSING) to listOf(0L to 0, 1L to 0, 47_999L to 32460, 48_000L to 32631, 72_000L to -17261,
                96_000L to 2220, 518_399L to 0, 124_800L to 17, 134_400L to -7006),
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
            val pcm = PcmRenderer(icon, 48_000, model).toShortArray()
            for ((index, value) in expected.getValue(icon.name to model)) {
                assertEquals("${icon.name} $model sample $index", value, pcm[index.toInt()].toInt())
                assertEquals("${icon.name} $model reference $index", value, IconReference.pcm(IconReference.sample(icon, model, index, 48_000)))
            }
        }
    }
}
