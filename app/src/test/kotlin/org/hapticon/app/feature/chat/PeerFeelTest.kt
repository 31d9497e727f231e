package org.hapticon.app.feature.chat

import org.hapticon.core.pattern.toPattern
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import org.junit.Assert.assertEquals
import org.junit.Test

/** How a peer's phone plays a pattern, from the capabilities it publishes (PatternPlan.of's rules). */
class PeerFeelTest {
    private fun feel(renderer: RendererKind, amplitude: Boolean = true, api: Int? = 35) =
        PeerFeel.ofPattern(Capabilities("bob", renderer, amplitude, api))

    @Test
    fun ofPattern_audioCoupledApi36_envelopeOrAmplitudeSteps() =
        assertEquals(PeerFeel(RendererKind.ENVELOPE, null, RendererKind.AMPLITUDE_WAVEFORM), feel(RendererKind.AUDIO_COUPLED, api = 36))

    @Test
    fun ofPattern_audioCoupledBelowApi36_amplitudeSteps() =
        assertEquals(PeerFeel(RendererKind.AMPLITUDE_WAVEFORM, null), feel(RendererKind.AUDIO_COUPLED, api = 35))

    @Test
    fun ofPattern_audioCoupledUnknownApiWithoutAmplitudeControl_onOff() =
        assertEquals(PeerFeel(RendererKind.ON_OFF, null), feel(RendererKind.AUDIO_COUPLED, amplitude = false, api = null))

    @Test
    fun ofPattern_envelopeOnOffAndNone_asPublishedWithoutFidelity() {
        for (kind in listOf(RendererKind.ENVELOPE, RendererKind.ON_OFF, RendererKind.NONE, RendererKind.AMPLITUDE_WAVEFORM)) {
            assertEquals(PeerFeel(kind, null), feel(kind, api = 36))
        }
    }

    @Test
    fun ofPattern_audioCoupledPeerOfThisBuild_playsThePatternAsAudioAtItsOwnPitch() {
        val caps = Capabilities("bob", RendererKind.AUDIO_COUPLED, true, 36, envelopeEffects = false)
        val pattern = org.hapticon.core.HapticIcon.STROKE.toPattern()
        assertEquals(
            PeerFeel(RendererKind.AUDIO_COUPLED, null, pitch = "bob's phone: 349 Hz → plays 349 Hz (audio haptic channel)"),
            PeerFeel.ofPattern(caps, pattern),
        )
    }
}
