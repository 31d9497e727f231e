package org.hapticon.app.playback

import org.hapticon.core.HapticIcon
import org.hapticon.messaging.RendererKind
import org.junit.Assert.assertEquals
import org.junit.Test

class RendererChoiceTest {
    private val base = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)

    @Test
    fun choose_noVibrator_none() =
        assertEquals(AdaptiveRenderer.NONE, RendererChoice.choose(base.copy(hasVibrator = false), HapticIcon.HUG))

    @Test
    fun choose_noAmplitudeControl_onOff() =
        assertEquals(AdaptiveRenderer.ON_OFF, RendererChoice.choose(base.copy(hasAmplitudeControl = false), HapticIcon.HUG))

    @Test
    fun choose_amplitudeControlApi35_amplitudeWaveform() =
        assertEquals(AdaptiveRenderer.AMPLITUDE_WAVEFORM, RendererChoice.choose(base, HapticIcon.HUG))

    @Test
    fun choose_api36EnvelopeSupportedSmoothIcon_envelope() =
        assertEquals(AdaptiveRenderer.ENVELOPE, RendererChoice.choose(base.copy(apiLevel = 36, envelopeEffectsSupported = true), HapticIcon.HUG))

    @Test
    fun choose_api36WithoutEnvelopeSupport_amplitudeWaveform() =
        assertEquals(AdaptiveRenderer.AMPLITUDE_WAVEFORM, RendererChoice.choose(base.copy(apiLevel = 36), HapticIcon.HUG))

    @Test
    fun choose_envelopeFlagOnOldApi_ignored() =
        assertEquals(AdaptiveRenderer.AMPLITUDE_WAVEFORM, RendererChoice.choose(base.copy(envelopeEffectsSupported = true), HapticIcon.HUG))

    @Test
    fun choose_hapticPlaybackSupported_notImplementedSoEnvelope() =
        assertEquals(
            AdaptiveRenderer.ENVELOPE,
            RendererChoice.choose(base.copy(apiLevel = 36, envelopeEffectsSupported = true, hapticPlaybackSupported = true), HapticIcon.HUG),
        )

    @Test
    fun choose_overrideAvailable_wins() =
        assertEquals(AdaptiveRenderer.ON_OFF, RendererChoice.choose(base, HapticIcon.HUG, override = AdaptiveRenderer.ON_OFF))

    @Test
    fun choose_overrideUnavailable_automaticChoice() =
        assertEquals(AdaptiveRenderer.AMPLITUDE_WAVEFORM, RendererChoice.choose(base, HapticIcon.HUG, override = AdaptiveRenderer.ENVELOPE))

    @Test
    fun capabilitiesOf_envelopePhone_announcesAmplitudeWaveform() {
        val caps = RendererChoice.capabilitiesOf("alice", base.copy(apiLevel = 36, envelopeEffectsSupported = true, resonantFrequencyHz = 170.0), null)
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, caps.renderer)
        assertEquals(170.0, caps.resonantFrequencyHz!!, 0.0)
    }

    @Test
    fun fidelityPercent_onOffBelowAmplitude() {
        val amplitude = RendererChoice.fidelityPercent(AdaptiveRenderer.AMPLITUDE_WAVEFORM, HapticIcon.HUG)!!
        val onOff = RendererChoice.fidelityPercent(AdaptiveRenderer.ON_OFF, HapticIcon.HUG)!!
        assert(onOff < amplitude) { "on/off $onOff should be below amplitude $amplitude" }
        assertEquals(null, RendererChoice.fidelityPercent(AdaptiveRenderer.NONE, HapticIcon.HUG))
    }
}
