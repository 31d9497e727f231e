package org.hapticon.app.playback

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.RendererKind
import org.junit.Assert.assertEquals
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

// Robolectric: fidelityPercent marks its rendering for StrictMode, which needs the Android runtime.
@RunWith(RobolectricTestRunner::class)
class RendererChoiceTest {
    private val base = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)

    /** An Android 16 phone that does everything. */
    private val AUDIO_PHONE = base.copy(apiLevel = 36, envelopeEffectsSupported = true, hapticPlaybackSupported = true, hapticGeneratorAvailable = true)

    @Test
    fun choose_noVibrator_none() =
        assertEquals(RendererKind.NONE, RendererChoice.choose(base.copy(hasVibrator = false), HapticIcon.HUG))

    @Test
    fun choose_noAmplitudeControl_onOff() =
        assertEquals(RendererKind.ON_OFF, RendererChoice.choose(base.copy(hasAmplitudeControl = false), HapticIcon.HUG))

    @Test
    fun choose_amplitudeControlApi35_amplitudeWaveform() =
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, RendererChoice.choose(base, HapticIcon.HUG))

    @Test
    fun choose_api36EnvelopeSupportedSmoothIcon_envelope() =
        assertEquals(RendererKind.ENVELOPE, RendererChoice.choose(base.copy(apiLevel = 36, envelopeEffectsSupported = true), HapticIcon.HUG))

    @Test
    fun choose_api36WithoutEnvelopeSupport_amplitudeWaveform() =
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, RendererChoice.choose(base.copy(apiLevel = 36), HapticIcon.HUG))

    @Test
    fun choose_envelopeFlagOnOldApi_ignored() =
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, RendererChoice.choose(base.copy(envelopeEffectsSupported = true), HapticIcon.HUG))

    @Test
    fun choose_hapticPlaybackAndGenerator_audioCoupledFirst() =
        assertEquals(
            RendererKind.AUDIO_COUPLED,
            RendererChoice.choose(AUDIO_PHONE, HapticIcon.HUG),
        )

    @Test
    fun choose_hapticPlaybackWithoutGenerator_envelope() =
        assertEquals(
            RendererKind.ENVELOPE,
            RendererChoice.choose(AUDIO_PHONE.copy(hapticGeneratorAvailable = false), HapticIcon.HUG),
        )

    @Test
    fun choose_audioFlagsBelowApi31_ignored() =
        assertEquals(
            RendererKind.AMPLITUDE_WAVEFORM,
            RendererChoice.choose(base.copy(apiLevel = 30, hapticPlaybackSupported = true, hapticGeneratorAvailable = true), HapticIcon.HUG),
        )

    @Test
    fun choose_overrideAvailable_wins() =
        assertEquals(RendererKind.ON_OFF, RendererChoice.choose(base, HapticIcon.HUG, override = RendererKind.ON_OFF))

    @Test
    fun choose_overrideUnavailable_automaticChoice() =
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, RendererChoice.choose(base, HapticIcon.HUG, override = RendererKind.ENVELOPE))

    @Test
    fun capabilitiesOf_envelopePhone_announcesEnvelope() {
        val caps = RendererChoice.capabilitiesOf("alice", base.copy(apiLevel = 36, envelopeEffectsSupported = true, resonantFrequencyHz = 170.0), null)
        assertEquals(RendererKind.ENVELOPE, caps.renderer)
        assertEquals(170.0, caps.resonantFrequencyHz!!, 0.0)
    }

    @Test
    fun capabilitiesOf_audioPhone_announcesAudioCoupledAndTheOverrideWhenPossible() {
        assertEquals(RendererKind.AUDIO_COUPLED, RendererChoice.capabilitiesOf("alice", AUDIO_PHONE, null).renderer)
        assertEquals(RendererKind.ON_OFF, RendererChoice.capabilitiesOf("alice", AUDIO_PHONE, RendererKind.ON_OFF).renderer)
    }

    @Test
    fun possible_neverOffersWireOnlyKinds() {
        // AUDIO (the CLI's WAV files) and UNKNOWN exist only on the wire: a phone never picks them for itself.
        val options = RendererChoice.possible(AUDIO_PHONE.copy(apiLevel = 36, envelopeEffectsSupported = true), null)
        assertEquals(listOf(RendererKind.AUDIO_COUPLED, RendererKind.ENVELOPE, RendererKind.AMPLITUDE_WAVEFORM, RendererKind.ON_OFF), options)
    }

    @Test
    fun fidelityPercent_audioCoupledIsThePcm16Rendering() {
        // PCM16 rounding leaves ~1e-5 RMS of full scale: 100 % after rounding to whole percent.
        assertEquals(100, RendererChoice.fidelityPercent(RendererKind.AUDIO_COUPLED, HapticIcon.KNOCK))
    }

    @Test
    fun fidelityPercent_onOffBelowAmplitude() {
        val amplitude = RendererChoice.fidelityPercent(RendererKind.AMPLITUDE_WAVEFORM, HapticIcon.HUG)!!
        val onOff = RendererChoice.fidelityPercent(RendererKind.ON_OFF, HapticIcon.HUG)!!
        assert(onOff < amplitude) { "on/off $onOff should be below amplitude $amplitude" }
        assertEquals(null, RendererChoice.fidelityPercent(RendererKind.NONE, HapticIcon.HUG))
    }
}
