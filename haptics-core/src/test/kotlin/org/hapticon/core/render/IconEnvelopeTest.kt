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
        val e = HapticIcon.HUG.envelope()
        assertEquals(0.0, e.sample(0.0), 0.0)
        assertEquals(0.25, e.sample(0.75), tolerance)
        assertEquals(0.5, e.sample(2.0), tolerance)
        assertEquals(0.1, e.sample(2.9), tolerance)
        assertEquals(0.0, e.sample(3.0), 0.0)
    }

    @Test
    fun envelope_processingHug_sustainIsARampFromOneToLevel() {
        val e = HapticIcon.HUG.envelope(EnvelopeModel.PROCESSING)
        assertEquals(0.5, e.sample(0.75), tolerance)
        assertEquals(1.0, e.sample(1.5), tolerance)
        assertEquals(0.75, e.sample(2.0), tolerance)
        assertEquals(0.25, e.sample(2.75), tolerance)
    }

    @Test
    fun envelope_strokeAt2point8s_isTheMaxOfOverlappingRepetitions() {
        assertEquals(0.06, HapticIcon.STROKE.envelope().sample(2.8), tolerance)
        assertEquals(0.2, HapticIcon.STROKE.envelope(EnvelopeModel.PROCESSING).sample(2.8), tolerance)
    }

    @Test
    fun envelope_zeroAttack_startsAtLevel() {
        val icon = HapticIcon("step", 0.0, 0.5, 0.4, 0.5, 60.0)
        assertEquals(0.4, icon.envelope().sample(0.0), 0.0)
        assertEquals(1.0, icon.envelope(EnvelopeModel.PROCESSING).sample(0.0), 0.0)
    }

    @Test
    fun envelope_paperSampledAtRenderRate_equalsRendererEnvelopeForPresets() {
        for (icon in HapticIcon.PRESETS) {
            val e = icon.envelope()
            val renderer = IconRenderer(icon, 8_000)
            for (i in 0 until renderer.sampleCount step 37) {
                assertEquals("${icon.name} $i", e.sample(i / 8_000.0), renderer.envelopeAt(i), tolerance)
            }
        }
    }
}
