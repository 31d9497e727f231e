package org.hapticon.core.pattern

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.EnvelopeModel
import org.hapticon.core.render.envelope
import org.junit.Assert.assertEquals
import org.junit.Test

class IconPatternTest {
    private fun keys(vararg pairs: Pair<Double, Double>) = pairs.map { AmplitudeKey(it.first, it.second) }

    private fun assertKeys(expected: List<AmplitudeKey>, actual: List<AmplitudeKey>) {
        assertEquals("key count in $actual", expected.size, actual.size)
        expected.zip(actual).forEach { (e, a) ->
            assertEquals("time in $actual", e.time, a.time, 1e-12)
            assertEquals("amplitude at ${e.time} in $actual", e.amplitude, a.amplitude, 1e-12)
        }
    }

    @Test
    fun hug_paper_oneTrapezoidAndItsNote() {
        val pattern = HapticIcon.HUG.toPattern(EnvelopeModel.PAPER)
        assertKeys(keys(0.0 to 0.0, 1.5 to 0.5, 2.5 to 0.5, 3.0 to 0.0), pattern.amplitude)
        assertEquals(listOf(FrequencyKey(0.0, HapticIcon.HUG.frequency)), pattern.frequency)
        assertEquals(3.0, pattern.duration, 0.0)
    }

    @Test
    fun hug_processing_attacksToFullThenDecaysToTheLevelOverTheSustain() {
        // Processing Sound's Env.play: attack to full amplitude, "gradual decay towards sustain level across
        // entire sustain period", release. The default model.
        assertKeys(keys(0.0 to 0.0, 1.5 to 1.0, 2.5 to 0.5, 3.0 to 0.0), HapticIcon.HUG.toPattern().amplitude)
    }

    @Test
    fun processingPattern_matchesTheContinuousProcessingEnvelope() {
        for (icon in HapticIcon.PRESETS) {
            val pattern = icon.toPattern()
            val envelope = icon.envelope(EnvelopeModel.PROCESSING)
            for (i in 0..400) {
                val t = icon.duration * i / 400
                // The continuous envelope runs on Processing's float parameters and sample grid (44.1 kHz).
                assertEquals("${icon.name} at $t", envelope.sample(t), pattern.amplitudeAt(t), 0.02)
            }
        }
    }

    @Test
    fun knock_threeRepetitions_cornersEvery270ms() {
        val amplitude = HapticIcon.KNOCK.toPattern(EnvelopeModel.PAPER).amplitude
        assertEquals(12, amplitude.size)
        assertKeys(keys(0.27 to 0.0, 0.275 to 0.5, 0.285 to 0.5, 0.29 to 0.0), amplitude.subList(4, 8))
        assertEquals(0.56, amplitude.last().time, 1e-12)
    }

    @Test
    fun stroke_processing_overlappingRepetitionsAdd() {
        // Repetition 1 releases 0.12 → 0 over 2.6–3.0 s while repetition 2 attacks 0 → 0.4 (to 1 at 3.6 s): they add.
        val amplitude = HapticIcon.STROKE.toPattern().amplitude
        assertKeys(keys(0.0 to 0.0, 1.0 to 1.0, 2.0 to 0.3, 2.6 to 0.12, 3.0 to 0.4, 3.6 to 1.0), amplitude.take(6))
        assertEquals(0.26, HapticIcon.STROKE.toPattern().amplitudeAt(2.8), 1e-12)
    }

    @Test
    fun stroke_paper_addsTheCrossingOfTheTwoTrapezoids() {
        val amplitude = HapticIcon.STROKE.toPattern(EnvelopeModel.PAPER).amplitude
        // 2.6 and 3.0 s lie on the straight releases and attacks, so only the crossing remains a corner there.
        assertKeys(keys(2.0 to 0.3, 2.8 to 0.06, 3.6 to 0.3), amplitude.subList(2, 5))
    }

    @Test
    fun zeroAttackAndRelease_becomeSteps() {
        val icon = HapticIcon("block", attack = 0.0, sustain = 0.1, level = 0.8, release = 0.0, note = 60.0, period = 0.2, count = 2)
        val pattern = icon.toPattern(EnvelopeModel.PAPER)
        assertKeys(keys(0.0 to 0.8, 0.1 to 0.8, 0.1 to 0.0, 0.2 to 0.0, 0.2 to 0.8, 0.3 to 0.8, 0.3 to 0.0), pattern.amplitude)
        assertEquals(0.8, pattern.amplitudeAt(0.0), 0.0)
        assertEquals(0.0, pattern.amplitudeAt(0.1), 0.0)
        assertEquals(0.0, pattern.amplitudeAt(0.15), 0.0)
        assertEquals(0.8, pattern.amplitudeAt(0.2), 0.0)
        // Under Processing the attack jumps to full and the sustain decays to 0.8.
        assertEquals(0.9, icon.toPattern().amplitudeAt(0.05), 1e-12)
    }

    @Test
    fun sumOverCapacity_isCappedAtOne() {
        val icon = HapticIcon("dense", attack = 0.0, sustain = 1.0, level = 0.7, release = 0.0, note = 60.0, period = 0.5, count = 2)
        assertEquals(1.0, icon.toPattern().amplitudeAt(0.75), 0.0)
        assertEquals(0.7, icon.toPattern(EnvelopeModel.PAPER).amplitudeAt(0.75), 0.0)
    }
}
