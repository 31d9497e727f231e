package org.hapticon.app.playback

import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternEnvelope
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import java.util.Locale
import kotlin.math.abs

/**
 * The pitch a peer's phone will give an icon or pattern, from the capabilities it publishes (frequency profile,
 * envelope support, resonant frequency, pitch fit) and the same rules this phone plays by ([PatternPlan.of]), as
 * one line for the sender: "bob's phone (120–240 Hz): 349 Hz → plays 175 Hz, shifted down one octave".
 */
object PeerPitch {
    /**
     * The peer's phone as [PatternPlan.of] needs it, with the envelope limits it publishes ([Capabilities.envelopeLimits]);
     * a peer that does not publish them (an older build) gets the guaranteed ones ([EnvelopeEffectInfo.GUARANTEED]:
     * 16 points, 20 ms..1 s), and [describeEnvelope] says so. A peer that does not say whether it has envelope effects
     * (an older build) is taken to have them when its renderer is the envelope.
     */
    fun deviceOf(caps: Capabilities): DeviceCapabilities {
        val envelope = caps.envelopeEffects ?: (caps.renderer == RendererKind.ENVELOPE)
        // Builds that publish envelopeEffects also play patterns as audio where they play icons so; older ones do not.
        val audio = caps.renderer == RendererKind.AUDIO_COUPLED && caps.envelopeEffects != null
        return DeviceCapabilities(
            hasVibrator = caps.renderer != RendererKind.NONE && caps.renderer != RendererKind.AUDIO,
            hasAmplitudeControl = caps.amplitudeControl,
            apiLevel = caps.apiLevel ?: 0,
            resonantFrequencyHz = caps.resonantFrequencyHz,
            envelopeEffectsSupported = envelope,
            frequencyRangeHz = caps.frequencyRangeHz,
            envelopeInfo = if (envelope) caps.envelopeLimits ?: EnvelopeEffectInfo.GUARANTEED else null,
            hapticPlaybackSupported = audio,
            hapticGeneratorAvailable = audio,
        )
    }

    /** How the peer plays [pattern]: its published renderer stands for a renderer it forces (steps or on/off). */
    fun planOf(caps: Capabilities, pattern: HapticPattern): PatternPlan {
        val override = caps.renderer.takeIf { it == RendererKind.AMPLITUDE_WAVEFORM || it == RendererKind.ON_OFF }
        return PatternPlan.of(deviceOf(caps), pattern, override, caps.pitchFit ?: PitchFit.OCTAVES)
    }

    /**
     * The line for [pattern] (an [icon]'s as [org.hapticon.core.pattern.toPattern]) on [caps]'s phone; [audioCoupled]
     * when the peer plays it as audio with the haptic channel (icons on such phones), which carries the sine at the
     * pattern's own frequency. Null when the peer plays nothing or is not a phone (the CLI's audio, unknown).
     * [knownPlan] is [planOf] when the caller has it already, so one composer choice plans the pattern once.
     */
    fun describe(
        caps: Capabilities,
        pattern: HapticPattern,
        audioCoupled: Boolean = false,
        icon: Boolean = false,
        knownPlan: PatternPlan? = null,
    ): String? {
        val phone = "${caps.user}'s phone"
        val own = hzRange(pattern)
        if (audioCoupled) return "$phone: $own → plays $own (audio haptic channel)"
        if (caps.renderer == RendererKind.AUDIO || caps.renderer == RendererKind.UNKNOWN) return null
        val plan = knownPlan ?: planOf(caps, pattern)
        // Builds older than the published envelopeEffects play an icon's envelope with a fixed sharpness of 0.5.
        if (icon && caps.envelopeEffects == null && plan is PatternPlan.Envelope) return "$phone (an older Hapticon): $own → sharpness 0.50, the note is not played"
        return when (plan) {
            PatternPlan.Silent -> null
            // The peer's published renderer is its choice for icons; audio-coupled is handled above for them.
            is PatternPlan.AudioCoupled -> "$phone: $own → plays $own (audio haptic channel)"
            is PatternPlan.Steps -> {
                val resonance = caps.resonantFrequencyHz?.let { " (${hz(it)})" } ?: ""
                if (deviceOf(caps).envelopeEffectsSupported && caps.renderer == RendererKind.ENVELOPE) {
                    "$phone: too quick for its envelope effect, amplitude steps at its resonance$resonance"
                } else {
                    "$phone has no pitch control: plays at its resonance$resonance"
                }
            }
            is PatternPlan.Envelope -> when (val envelope = plan.envelope) {
                is PatternEnvelope.Basic -> {
                    val sharpness = pattern.frequency.map { envelope.mapping.normalizedOf(it.hertz) }
                    val shown = if (sharpness.max() - sharpness.min() < 0.005) fixed(sharpness.first()) else "${fixed(sharpness.min())}–${fixed(sharpness.max())}"
                    "$phone has no frequency profile: $own → sharpness $shown"
                }
                is PatternEnvelope.Waveform -> {
                    val range = caps.frequencyRangeHz!!
                    val fitted = envelope.pitch
                    val how = when {
                        fitted.octaves != 0 -> ", shifted ${if (fitted.octaves > 0) "up" else "down"} ${octaves(abs(fitted.octaves))}" +
                            (if (fitted.clampedKeys > 0) " and clamped" else "")
                        fitted.clampedKeys > 0 -> ", clamped"
                        else -> ""
                    }
                    "$phone (${String.format(Locale.ROOT, "%.0f–%.0f Hz", range.start, range.endInclusive)}): $own → plays ${hzRange(fitted.pattern)}$how"
                }
            }
        }
    }

    /**
     * The line for how [caps]'s phone resamples [pattern] into its envelope effect: the control points it will send,
     * resampled by the same [PatternEnvelope.of] its API 36 renderer runs, within the limits it publishes, e.g.
     * "bob's envelope: 4 control points (7 merged into 4 by its limits: 4 points, 50 ms–1 s each, 4 s in all)", where
     * 7 is what the guaranteed limits would give; "… (limits not published; assumed 16 points, 20 ms–1 s each, 16 s in
     * all)" for a peer that does not publish them; "bob's envelope cannot follow it within its limits (…)" when the peer
     * plays steps instead. Null when the peer plays no envelope effect (audio-coupled, steps by its own choice, none)
     * and for an [icon] on an older build, which renders icons with its own fixed points. [knownPlan]: as for [describe].
     */
    fun describeEnvelope(caps: Capabilities, pattern: HapticPattern, icon: Boolean = false, knownPlan: PatternPlan? = null): String? {
        if (icon && caps.envelopeEffects == null) return null
        val device = deviceOf(caps)
        if (!device.envelopeEffectsSupported || device.apiLevel < 36) return null
        val published = caps.envelopeLimits
        val limits = limitsText(published ?: EnvelopeEffectInfo.GUARANTEED)
        return when (val plan = knownPlan ?: planOf(caps, pattern)) {
            is PatternPlan.Envelope -> {
                val count = pointsOf(plan.envelope)
                val points = if (count == 1) "1 control point" else "$count control points"
                val how = when {
                    published == null -> "limits not published; assumed $limits"
                    else -> {
                        // What the guaranteed limits would give, resampled by the same function: more points were merged.
                        val guaranteed = if (published == EnvelopeEffectInfo.GUARANTEED) null else PatternEnvelope.of(
                            pattern, EnvelopeEffectInfo.GUARANTEED, device.frequencyRangeHz, caps.pitchFit ?: PitchFit.OCTAVES,
                        )?.let(::pointsOf)
                        if (guaranteed != null && guaranteed > count) "$guaranteed merged into $count by its limits: $limits" else "its limits: $limits"
                    }
                }
                "${caps.user}'s envelope: $points ($how)"
            }
            // Steps on a phone that plays the envelope by choice: the envelope could not follow the pattern within the limits.
            is PatternPlan.Steps -> if (caps.renderer == RendererKind.ENVELOPE) {
                "${caps.user}'s envelope cannot follow it within " + (if (published == null) "the assumed limits ($limits; not published)" else "its limits ($limits)")
            } else {
                null
            }
            else -> null
        }
    }

    private fun pointsOf(envelope: PatternEnvelope): Int = when (envelope) {
        is PatternEnvelope.Waveform -> envelope.points.size
        is PatternEnvelope.Basic -> envelope.points.size
    }

    // "4 points, 50 ms–1 s each, 4 s in all"
    private fun limitsText(info: EnvelopeEffectInfo): String {
        val min = info.minControlPointMillis
        val max = info.maxControlPointMillis
        val each = if (max < 1000) "$min–$max ms" else "${millis(min)}–${millis(max)}"
        val points = if (info.maxControlPoints == 1) "1 point" else "${info.maxControlPoints} points"
        return "$points, $each each, ${millis(info.maxDurationMillis)} in all"
    }

    private fun millis(value: Long): String = when {
        value < 1000 -> "$value ms"
        value % 1000 == 0L -> "${value / 1000} s"
        value % 100 == 0L -> String.format(Locale.ROOT, "%.1f s", value / 1000.0)
        else -> "$value ms"
    }

    private fun hzRange(pattern: HapticPattern): String {
        val low = hz(pattern.frequency.minOf { it.hertz })
        val high = hz(pattern.frequency.maxOf { it.hertz })
        return if (low == high) low else "${low.removeSuffix(" Hz")}–$high"
    }

    private fun hz(value: Double) = String.format(Locale.ROOT, "%.0f Hz", value)

    private fun fixed(value: Double) = String.format(Locale.ROOT, "%.2f", value)

    private fun octaves(n: Int) = when (n) {
        1 -> "one octave"
        2 -> "two octaves"
        3 -> "three octaves"
        else -> "$n octaves"
    }
}
