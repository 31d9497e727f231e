package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Test

class IconEnvelopeTest {
    private val tolerance = 1e-12

    @Test
    fun envelope_presets_lastTheIconDuration() {
        for (icon in HapticIcon.PRESETS) for (model in EnvelopeModel.values()) {
            assertEquals("${icon.name} $model", icon.duration, icon.envelope(model).length, tolerance)
        }
    }

    @Test
    fun envelope_paperHug_rampsHoldsAndReleases() {
        // hug: 1.5 s attack to 0.5, 1.0 s sustain, 0.5 s release.
        val e = HapticIcon.HUG.envelope(EnvelopeModel.PAPER)
        assertEquals(0.0, e.sample(0.0), 0.0)
        assertEquals(0.25, e.sample(0.75), tolerance)
        assertEquals(0.5, e.sample(2.0), tolerance)
        assertEquals(0.1, e.sample(2.9), tolerance)
        assertEquals(0.0, e.sample(3.0), 0.0)
    }

    @Test
    fun envelope_processingHug_sustainIsARampFromOneToLevel() {
        // Processing Sound at its own 44.1 kHz: 1.5 s attack to 1, 1 s sustain ramp 1 → 0.5, 0.5 s release.
        val e = HapticIcon.HUG.envelope(EnvelopeModel.PROCESSING)
        assertEquals(0.5, e.sample(0.75), 1e-9)
        assertEquals(1.0, e.sample(1.5), 1e-9)
        assertEquals(0.75, e.sample(2.0), 1e-9)
        assertEquals(0.25, e.sample(2.75), 1e-9)
    }

    @Test
    fun envelope_strokeAt2point8s_combinesOverlappingRepetitionsPerModel() {
        // Repetition 0 is 0.8 s into its release, repetition 1 0.2 s into its attack.
        assertEquals(0.06, HapticIcon.STROKE.envelope(EnvelopeModel.PAPER).sample(2.8), tolerance)
        // Processing adds them: release 0.3f · 0.2 plus attack 0.2 (level 0.3 passes through Env.play's float).
        assertEquals(0.2 + 0.3f.toDouble() * 0.2, HapticIcon.STROKE.envelope(EnvelopeModel.PROCESSING).sample(2.8), 1e-11)
    }

    @Test
    fun envelope_zeroAttack_paperStartsAtLevelProcessingSpendsOneSampleRising() {
        val icon = HapticIcon("step", 0.0, 0.5, 0.4, 0.5, 60.0)
        assertEquals(0.4, icon.envelope(EnvelopeModel.PAPER).sample(0.0), 0.0)
        // A 0 s attack lasts one sample in JSyn: 0 at sample 0, the attack target 1 at sample 1.
        val processing = icon.envelope(EnvelopeModel.PROCESSING)
        assertEquals(0.0, processing.sample(0.0), 0.0)
        assertEquals(1.0, processing.sample(1.0 / 44_100), 1e-12)
    }

    @Test
    fun envelope_sampledAtRenderRate_equalsRendererEnvelopeForPresetsInBothModels() {
        for (model in EnvelopeModel.values()) for (icon in HapticIcon.PRESETS) {
            val e = icon.envelope(model, 8_000)
            val renderer = IconRenderer(icon, 8_000, model)
            for (i in 0 until renderer.sampleCount step 37) {
                assertEquals("${icon.name} $model $i", renderer.envelopeAt(i), e.sample(i / 8_000.0), 1e-12)
            }
        }
    }
}
