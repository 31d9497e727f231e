package org.hapticon.app.playback

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.pattern.toPattern
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Test

/** The sender's line for the pitch a peer's phone will play, from the capabilities the peer publishes. */
class PeerPitchTest {
    private fun bob(
        renderer: RendererKind = RendererKind.ENVELOPE,
        range: ClosedFloatingPointRange<Double>? = 120.0..240.0,
        fit: PitchFit? = PitchFit.OCTAVES,
        envelope: Boolean? = true,
    ) = Capabilities("bob", renderer, amplitudeControl = true, apiLevel = 36, resonantFrequencyHz = 170.0, envelopeEffects = envelope, frequencyRangeHz = range, pitchFit = fit)

    private val stroke = HapticIcon.STROKE.toPattern() // note 65, 349.2 Hz
    private val hug = HapticIcon.HUG.toPattern() // note 50, 146.8 Hz
    private val low = HapticPattern("low", listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.2, 1.0), AmplitudeKey(0.4, 0.0)), listOf(FrequencyKey(0.0, 60.0)))

    @Test
    fun narrowProfile_octaves_namesTheShift() {
        assertEquals("bob's phone (120–240 Hz): 349 Hz → plays 175 Hz, shifted down one octave", PeerPitch.describe(bob(), stroke))
        assertEquals("bob's phone (120–240 Hz): 60 Hz → plays 120 Hz, shifted up one octave", PeerPitch.describe(bob(), low))
        assertEquals("bob's phone (120–240 Hz): 147 Hz → plays 147 Hz", PeerPitch.describe(bob(), hug))
    }

    @Test
    fun narrowProfile_clamp_thePeersOwnSetting() {
        assertEquals("bob's phone (120–240 Hz): 349 Hz → plays 240 Hz, clamped", PeerPitch.describe(bob(fit = PitchFit.CLAMP), stroke))
    }

    @Test
    fun olderPeer_noFitPublished_octavesAsItsBuildPlays() {
        assertEquals("bob's phone (120–240 Hz): 349 Hz → plays 175 Hz, shifted down one octave", PeerPitch.describe(bob(fit = null), stroke))
    }

    @Test
    fun noFrequencyProfile_sharpnessFromTheNote() {
        // Note 65 on the C2..C5 scale: (65 − 36) / 36 = 0.81.
        assertEquals("bob's phone has no frequency profile: 349 Hz → sharpness 0.81", PeerPitch.describe(bob(range = null), stroke))
    }

    @Test
    fun amplitudePhone_noPitchControl_namesItsResonance() {
        val caps = bob(RendererKind.AMPLITUDE_WAVEFORM, range = null, envelope = false)
        assertEquals("bob's phone has no pitch control: plays at its resonance (170 Hz)", PeerPitch.describe(caps, stroke))
    }

    @Test
    fun audioCoupledIcon_theHapticChannelCarriesTheNote() {
        assertEquals("bob's phone: 349 Hz → plays 349 Hz (audio haptic channel)", PeerPitch.describe(bob(RendererKind.AUDIO_COUPLED), stroke, audioCoupled = true))
    }

    @Test
    fun cliAudioOrNothing_noLine() {
        assertNull(PeerPitch.describe(bob(RendererKind.AUDIO, envelope = false), stroke))
        assertNull(PeerPitch.describe(Capabilities("bob", RendererKind.NONE, false), stroke))
    }

    @Test
    fun olderPeerBuild_iconOnTheEnvelope_fixedSharpnessSaid() {
        val old = Capabilities("bob", RendererKind.ENVELOPE, amplitudeControl = true, apiLevel = 36, resonantFrequencyHz = 170.0)
        assertEquals("bob's phone (an older Hapticon): 349 Hz → sharpness 0.50, the note is not played", PeerPitch.describe(old, stroke, icon = true))
    }

    @Test
    fun envelopePhone_patternTooQuickForTheEnvelope_stepsSaidAsSuch() {
        // Knock's 20 ms pulses: no control points follow them, so an envelope phone plays amplitude steps.
        val knock = HapticIcon.KNOCK.toPattern()
        assertEquals("bob's phone: too quick for its envelope effect, amplitude steps at its resonance (170 Hz)", PeerPitch.describe(bob(), knock))
        assertEquals(
            org.hapticon.app.feature.chat.PeerFeel(
                RendererKind.AMPLITUDE_WAVEFORM, null, pitch = PeerPitch.describe(bob(), knock),
                envelope = "bob's envelope cannot follow it within the assumed limits (16 points, 20 ms–1 s each, 16 s in all; not published)",
            ),
            org.hapticon.app.feature.chat.PeerFeel.ofPattern(bob(), knock),
        )
    }

    // Two 40 ms triangles 200 ms apart: six segments of 20 ms or more.
    private val taps = HapticPattern(
        "taps",
        listOf(
            AmplitudeKey(0.0, 0.0), AmplitudeKey(0.02, 1.0), AmplitudeKey(0.04, 0.0), AmplitudeKey(0.2, 0.0),
            AmplitudeKey(0.22, 1.0), AmplitudeKey(0.24, 0.0), AmplitudeKey(0.4, 0.0),
        ),
        listOf(FrequencyKey(0.0, 150.0)),
    )

    @Test
    fun publishedLimits_guaranteedOnes_sixPointsNothingMerged() {
        val caps = bob().copy(envelopeLimits = EnvelopeEffectInfo.GUARANTEED)
        assertEquals("bob's envelope: 6 control points (its limits: 16 points, 20 ms–1 s each, 16 s in all)", PeerPitch.describeEnvelope(caps, taps))
        assertEquals("bob's phone (120–240 Hz): 150 Hz → plays 150 Hz", PeerPitch.describe(caps, taps))
    }

    @Test
    fun publishedLimits_50msMinimum_theTapsBecomeStepsAndBothLinesSaySo() {
        val caps = bob().copy(envelopeLimits = EnvelopeEffectInfo(4, 50, 1000, 4000))
        assertEquals("bob's envelope cannot follow it within its limits (4 points, 50 ms–1 s each, 4 s in all)", PeerPitch.describeEnvelope(caps, taps))
        assertEquals("bob's phone: too quick for its envelope effect, amplitude steps at its resonance (170 Hz)", PeerPitch.describe(caps, taps))
        assertEquals(RendererKind.AMPLITUDE_WAVEFORM, org.hapticon.app.feature.chat.PeerFeel.ofPattern(caps, taps).renderer)
    }

    @Test
    fun publishedLimits_shortControlPoints_longRampsCutAndDurationsInMs() {
        // At most 100 ms per point, 16 of them: taps' two 160 ms silences are cut in two each, 6 + 2 points.
        val caps = bob().copy(envelopeLimits = EnvelopeEffectInfo(16, 20, 100, 1600))
        assertEquals("bob's envelope: 8 control points (its limits: 16 points, 20–100 ms each, 1.6 s in all)", PeerPitch.describeEnvelope(caps, taps))
    }

    @Test
    fun noEnvelopeLine_forAudioStepsByChoiceOrAnOlderBuildsIcon() {
        assertNull(PeerPitch.describeEnvelope(bob(RendererKind.AUDIO_COUPLED), taps))
        assertNull(PeerPitch.describeEnvelope(bob(RendererKind.AMPLITUDE_WAVEFORM, envelope = false), taps))
        val old = Capabilities("bob", RendererKind.ENVELOPE, amplitudeControl = true, apiLevel = 36, resonantFrequencyHz = 170.0)
        assertNull(PeerPitch.describeEnvelope(old, HapticIcon.HUG.toPattern(), icon = true))
    }
}
