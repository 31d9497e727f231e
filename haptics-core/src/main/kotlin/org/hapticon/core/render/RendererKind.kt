package org.hapticon.core.render

/**
 * How a device turns an icon into something felt (or heard): the one renderer vocabulary of the app's player,
 * the chat's "how it will feel there" line and the capabilities a device publishes (messaging maps each value
 * to and from its wire name).
 */
public enum class RendererKind {
    /** Audio with the haptic channel on (Android audio-coupled haptics): the icon's own carrier, on the audio clock ([PcmRenderer]). */
    AUDIO_COUPLED,

    /** Android 16 envelope effect: the envelope as smooth control points, played by the vibrator HAL ([EnvelopeControlPoints]). */
    ENVELOPE,

    /** A vibrator with amplitude control plays the icon's envelope as amplitude steps ([VibrationWaveform.amplitudeSteps]). */
    AMPLITUDE_WAVEFORM,

    /** A vibrator without amplitude control plays an on/off pattern ([VibrationWaveform.onOff]). */
    ON_OFF,

    /** No actuator: the icon is rendered as audio (the command-line chat's WAV files). */
    AUDIO,

    /** The icon is not played at all. */
    NONE,

    /** A renderer named by a newer client that this build does not know. */
    UNKNOWN,
}
