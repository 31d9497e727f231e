package org.hapticon.app.feature.chat

import org.hapticon.app.playback.PeerPitch
import org.hapticon.app.playback.RendererChoice
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.toPattern
import org.hapticon.messaging.Capabilities
import org.hapticon.core.render.RendererKind

/**
 * What the peer's phone makes of the chosen icon or pattern ("how will this feel there"); [fidelityPercent] is
 * null for a pattern, where nothing plays, and while the chosen icon's figure is still being computed off the
 * main thread (`ConversationViewModel`). [alternative] is
 * set when the peer's capabilities leave two renderers possible (a pattern on an audio-coupled API 36 phone:
 * envelope if its vibrator offers envelope effects, else amplitude steps), shown as "X or Y".
 */
data class PeerFeel(
    val renderer: RendererKind,
    val fidelityPercent: Int?,
    val alternative: RendererKind? = null,
    /** The pitch the peer's phone will play, one line ([org.hapticon.app.playback.PeerPitch]); null when it plays none. */
    val pitch: String? = null,
    /**
     * The control points the peer's envelope effect will get, resampled within the limits it publishes (or the guaranteed
     * ones, said so), one line ([PeerPitch.describeEnvelope]); null when it plays no envelope effect.
     */
    val envelope: String? = null,
) {
    companion object {
        /**
         * How [caps]'s phone plays [icon]: its renderer, that renderer's fidelity and the pitch it will give the note.
         * The fidelity renders the icon, so the composer passes the figure it computed off the main thread (null until then).
         */
        fun ofIcon(
            caps: Capabilities,
            icon: HapticIcon,
            fidelityPercent: Int? = RendererChoice.fidelityPercent(caps.renderer, icon),
        ): PeerFeel {
            val pattern = icon.toPattern()
            val audioCoupled = caps.renderer == RendererKind.AUDIO_COUPLED
            // Planned once for both lines (it resamples the envelope); audio carries the icon whole and needs no plan.
            val plan = if (audioCoupled) null else PeerPitch.planOf(caps, pattern)
            return PeerFeel(
                caps.renderer, fidelityPercent,
                pitch = PeerPitch.describe(caps, pattern, audioCoupled = audioCoupled, icon = true, knownPlan = plan),
                // The peer's envelope renderer resamples the icon's pattern as it does a pattern; audio carries it whole.
                envelope = plan?.let { PeerPitch.describeEnvelope(caps, pattern, icon = true, knownPlan = it) },
            )
        }

        /**
         * How [caps]'s phone plays a pattern, following [org.hapticon.app.playback.PatternPlan.of]: audio-coupled where
         * the peer plays icons so (builds that publish `envelopeEffects`); an envelope effect needs API 36; otherwise
         * amplitude steps, or on/off without amplitude control. An older audio-coupled API 36 peer does not say
         * whether its vibrator has envelope effects, so it is "envelope or amplitude waveform".
         */
        fun ofPattern(caps: Capabilities, pattern: HapticPattern? = null): PeerFeel {
            val steps = if (caps.amplitudeControl) RendererKind.AMPLITUDE_WAVEFORM else RendererKind.ON_OFF
            // Planned once for every line below (planning resamples the envelope).
            val plan = pattern?.let { PeerPitch.planOf(caps, it) }
            val pitch = pattern?.let { PeerPitch.describe(caps, it, knownPlan = plan) }
            val envelope = pattern?.let { PeerPitch.describeEnvelope(caps, it, knownPlan = plan) }
            // A peer that publishes envelopeEffects (this build) is planned exactly: an envelope phone plays a pattern
            // its envelope cannot follow (a sharp pulse, or beyond its limits) as steps, and the line must say so.
            if (plan != null && caps.envelopeEffects != null && caps.renderer != RendererKind.AUDIO_COUPLED) {
                return PeerFeel(plan.renderer, null, pitch = pitch, envelope = envelope)
            }
            return when (caps.renderer) {
                RendererKind.AUDIO_COUPLED -> when {
                    // Builds that publish envelopeEffects play patterns as audio too; older ones plan them without audio,
                    // and do not say whether their vibrator has envelope effects.
                    caps.envelopeEffects != null -> PeerFeel(RendererKind.AUDIO_COUPLED, null, pitch = pitch)
                    (caps.apiLevel ?: 0) >= 36 -> PeerFeel(RendererKind.ENVELOPE, null, steps, pitch = pitch)
                    else -> PeerFeel(steps, null, pitch = pitch)
                }
                RendererKind.AMPLITUDE_WAVEFORM -> PeerFeel(steps, null, pitch = pitch)
                // Envelope, on/off, no actuator, the CLI's audio and unknown stay what the peer said.
                else -> PeerFeel(caps.renderer, null, pitch = pitch, envelope = envelope)
            }
        }
    }
}
