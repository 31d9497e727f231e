package org.hapticon.gesture.extraction

import org.hapticon.core.HapticIcon

/** A fitted icon and how it was fitted. */
public class IconFit(
    /** The icon, valid by [HapticIcon]'s own rules (out-of-range values clamped; see [FitReport.warnings]). */
    public val icon: HapticIcon,
    /** What was measured and how well the envelope model fits. */
    public val report: FitReport,
) {
    override fun toString(): String = "IconFit($icon, $report)"
}

/** What kind of signal a channel holds, decided from its dominant frequency. */
public enum class SignalKind {
    /** A vibration carrier (dominant frequency >= [IconFitter.CARRIER_MIN_HZ]): the note is the carrier's. */
    VIBRATION,

    /** A force or position signal without a carrier: the note comes from [ForceNote]. */
    FORCE,
}

/**
 * One fitted parameter: [value] as put in the icon, [measured] before any clamping (equal when nothing was
 * clamped), and [how] it was derived, in words.
 */
public class ParameterFit(
    /** Field name as in the icon JSON: attack, sustain, level, release, note, period or count. */
    public val name: String,
    /** The value in the icon. */
    public val value: Double,
    /** The value as measured, before clamping to the icon's safe ranges. */
    public val measured: Double,
    /** How it was derived. */
    public val how: String,
) {
    /** True when [value] differs from [measured] because a safety range clamped it. */
    public val clamped: Boolean get() = value != measured

    override fun toString(): String = "$name=$value${if (clamped) " (measured $measured)" else ""}: $how"
}

/**
 * Everything [IconFitter] measured. Times are in seconds of the recording; [fitRmsError] is relative to the
 * gesture's envelope peak (so 0.05 means the model is off by 5 % of the peak, on average).
 */
public class FitReport(
    /** The channel fitted. */
    public val channel: String,
    /** Its sample rate in Hz. */
    public val sampleRate: Double,
    /** Vibration carrier or force signal. */
    public val kind: SignalKind,
    /** Strongest frequency of the channel in Hz (0 for a signal with no oscillation). */
    public val dominantFrequencyHz: Double,
    /** Envelope detector used. */
    public val envelopeMethod: EnvelopeMethod,
    /** Its setting in words, e.g. "2nd-order Butterworth at 110.0 Hz, forward-backward". */
    public val envelopeSetting: String,
    /**
     * The gesture's peak in the channel's units (amplitude for a vibration, force above rest for a force):
     * the 99th percentile of the averaged repetition's envelope over the fitted span, at least the fitted
     * sustain amplitude — robust to single noise excursions.
     */
    public val envelopePeak: Double,
    /** What the level is relative to, in words with its value, e.g. "the input's full scale 1". */
    public val levelReference: String,
    /** The reference amplitude in the channel's units: the fitted level is the sustain amplitude divided by it. */
    public val levelReferenceValue: Double,
    /** The seven icon parameters in icon order: attack, sustain, level, release, note, period, count. */
    public val parameters: List<ParameterFit>,
    /** Onset of each repetition in seconds (the fitted attack start, aligned by threshold crossing). */
    public val onsets: List<Double>,
    /** RMS of the trapezoid fit residual relative to [envelopePeak]. */
    public val fitRmsError: Double,
    /** Coefficient of determination of the trapezoid fit. */
    public val rSquared: Double,
    /**
     * Estimated signal-to-noise ratio in dB: mean power inside the repetitions over the mean power of the quiet
     * part, noise subtracted; capped at [IconFitter.MAX_SNR_DB]. Null when no part of the recording is quiet.
     */
    public val snrDb: Double?,
    /** Anything doubtful: clamped parameters, clipping, a guessed force scale. Empty when all is well. */
    public val warnings: List<String>,
) {
    /** The parameter called [name]; throws [NoSuchElementException] for an unknown name. */
    public fun parameter(name: String): ParameterFit = parameters.first { it.name == name }

    override fun toString(): String =
        "FitReport($channel, $kind, ${parameters.joinToString()}, rms=$fitRmsError, r2=$rSquared, snr=$snrDb, warnings=$warnings)"
}

/** The recording holds nothing that looks like a gesture (silent, constant, or too short); the message says which. */
public class NoGestureException(message: String) : IllegalArgumentException("no gesture found: $message")
