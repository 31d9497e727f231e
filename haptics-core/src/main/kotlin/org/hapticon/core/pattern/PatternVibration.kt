package org.hapticon.core.pattern

import org.hapticon.core.render.EnvelopeControlPoints
import org.hapticon.core.render.Fidelity
import org.hapticon.core.render.VibrationWaveform
import kotlin.math.PI
import kotlin.math.ceil
import kotlin.math.cos

/**
 * The drive envelope of this pattern, 0..1 at a time in seconds: the amplitude curve plus every transient's
 * Hann window (peak intensity², as [signal] renders it), capped at 1. It is what a vibrator that follows
 * an amplitude (not a waveform) is asked to do.
 */
public fun HapticPattern.driveEnvelope(): (Double) -> Double {
    val taps = transients
    return { t ->
        var value = amplitudeAt(t)
        for (tap in taps) {
            val tau = t - tap.time
            if (tau in 0.0..Transient.DURATION_SECONDS) {
                value += tap.intensity * tap.intensity * (0.5 - 0.5 * cos(2.0 * PI * tau / Transient.DURATION_SECONDS))
            }
        }
        minOf(1.0, value)
    }
}

/**
 * This pattern as amplitude steps for `VibrationEffect.createWaveform` (every vibrator with amplitude control):
 * [VibrationWaveform.amplitudeSteps] of the [driveEnvelope]. The frequency curve is lost: such a vibrator plays at its
 * own resonance. Amplitudes stay in 0..255 ([VibrationWaveform]'s limit).
 *
 * @throws PatternException when the pattern plays longer than the safety cap ([HapticPattern.checkPlayable]).
 * @throws IllegalArgumentException when the pattern's duration rounds to 0 ms.
 */
public fun HapticPattern.vibrationWaveform(): VibrationWaveform = checkPlayable().let { VibrationWaveform.amplitudeSteps(driveEnvelope(), duration) }

/** This pattern for a vibrator without amplitude control: [VibrationWaveform.onOff] of the [driveEnvelope]. */
public fun HapticPattern.onOffWaveform(): VibrationWaveform = checkPlayable().let { VibrationWaveform.onOff(driveEnvelope(), duration) }

/**
 * What a vibrator accepts in an envelope effect: Android's `VibratorEnvelopeEffectInfo` (API 36).
 *
 * @property maxControlPoints `getMaxSize()`: most control points in one effect.
 * @property minControlPointMillis `getMinControlPointDurationMillis()`: shortest ramp between points.
 * @property maxControlPointMillis `getMaxControlPointDurationMillis()`: longest ramp between points.
 * @property maxDurationMillis `getMaxDurationMillis()`: longest effect.
 */
public data class EnvelopeEffectInfo(
    val maxControlPoints: Int,
    val minControlPointMillis: Long,
    val maxControlPointMillis: Long,
    val maxDurationMillis: Long,
) {
    public companion object {
        /**
         * What every device with envelope effects guarantees (Android's `VibratorEnvelopeEffectInfo` reference:
         * "at least 16 control points", "durations down to at least 20 milliseconds", "up to at least 1 second");
         * the total is then at most 16 s.
         */
        public val GUARANTEED: EnvelopeEffectInfo = EnvelopeEffectInfo(16, 20, 1000, 16_000)
    }
}

/**
 * A pattern as an API 36 envelope effect, ready for one of Android's two builders. Every effect starts at zero
 * amplitude (the builders do that) and its last point has amplitude 0, so the vibration ends quietly rather
 * than being cut off.
 */
public sealed interface PatternEnvelope {
    /** How closely the ramps follow the pattern's [driveEnvelope]. */
    public val fidelity: Fidelity

    /** Sum of the point durations. */
    public val totalMillis: Long

    /**
     * For `WaveformEnvelopeBuilder().setInitialFrequencyHz(initialHz)` then `addControlPoint(amplitude, hertz,
     * millis)` per point: the pattern's own frequencies in Hz, inside the actuator's range ([pitch] says how).
     */
    public data class Waveform(
        val initialHz: Double,
        val points: List<WaveformPoint>,
        val pitch: FittedPitch,
        override val fidelity: Fidelity,
    ) : PatternEnvelope {
        override val totalMillis: Long get() = points.sumOf { it.millis }
    }

    /**
     * For `BasicEnvelopeBuilder().setInitialSharpness(initialSharpness)` then `addControlPoint(intensity,
     * sharpness, millis)` per point: a phone that reports no frequency profile gets the frequency as a
     * sharpness 0..1, the normalised frequency of [FrequencyMapping] over [mapping].
     */
    public data class Basic(
        val initialSharpness: Double,
        val points: List<BasicPoint>,
        val mapping: FrequencyMapping,
        override val fidelity: Fidelity,
    ) : PatternEnvelope {
        override val totalMillis: Long get() = points.sumOf { it.millis }
    }

    /** One `WaveformEnvelopeBuilder` control point: reach [amplitude] 0..1 at [hertz] over [millis]. */
    public data class WaveformPoint(val amplitude: Double, val hertz: Double, val millis: Long)

    /** One `BasicEnvelopeBuilder` control point: reach [intensity] 0..1 and [sharpness] 0..1 over [millis]. */
    public data class BasicPoint(val intensity: Double, val sharpness: Double, val millis: Long)

    public companion object {
        /**
         * [pattern] as an envelope effect within [info], or null when it cannot be one (shorter than one
         * control point, longer than [EnvelopeEffectInfo.maxDurationMillis], or followed with a relative RMS
         * error above [EnvelopeControlPoints.REPRESENTABLE_RELATIVE_ERROR]; the caller then plays
         * [vibrationWaveform]).
         *
         * The amplitude is fitted by [EnvelopeControlPoints.fit] (least-squares straight segments of at least
         * the minimum duration); a segment longer than the maximum is cut into equal parts on the same line, and
         * the fit is redone with fewer points while that exceeds the point budget. Each point takes the pattern's
         * frequency at its end time. With a [frequencyRange] (the phone's `VibratorFrequencyProfile` min..max Hz)
         * the result is a [Waveform] whose frequencies were moved into the range by [fit] ([fitPitchInto]);
         * without one it is a [Basic] envelope with sharpness = `FrequencyMapping.DEFAULT.normalizedOf(hz)`.
         *
         * @throws PatternException when the pattern plays longer than the safety cap ([HapticPattern.checkPlayable]).
         */
        public fun of(
            pattern: HapticPattern,
            info: EnvelopeEffectInfo,
            frequencyRange: ClosedFloatingPointRange<Double>?,
            fit: PitchFit = PitchFit.OCTAVES,
        ): PatternEnvelope? {
            pattern.checkPlayable()
            if (info.maxControlPoints < 1 || info.minControlPointMillis < 1 || info.maxControlPointMillis < info.minControlPointMillis) return null
            val totalMillis = Math.round(pattern.duration * 1000)
            if (totalMillis < info.minControlPointMillis || totalMillis > info.maxDurationMillis) return null
            val usable = frequencyRange?.takeIf { it.start.isFinite() && it.endInclusive.isFinite() && it.start > 0 && it.endInclusive > it.start }
            val pitch = usable?.let { pattern.fitPitchInto(it.start, it.endInclusive, fit) }
            val played = pitch?.pattern ?: pattern
            val (ramps, fidelity) = fitRamps(played, info) ?: return null
            var endMillis = 0L
            val ends = ramps.map { (_, millis) -> endMillis += millis; endMillis / 1000.0 }
            return if (pitch != null) {
                Waveform(
                    initialHz = played.frequencyAt(0.0),
                    points = ramps.mapIndexed { i, (amplitude, millis) -> WaveformPoint(amplitude, played.frequencyAt(ends[i]), millis) },
                    pitch = pitch,
                    fidelity = fidelity,
                )
            } else {
                val mapping = FrequencyMapping.DEFAULT
                Basic(
                    initialSharpness = mapping.normalizedOf(played.frequencyAt(0.0)),
                    points = ramps.mapIndexed { i, (amplitude, millis) -> BasicPoint(amplitude, mapping.normalizedOf(played.frequencyAt(ends[i])), millis) },
                    mapping = mapping,
                    fidelity = fidelity,
                )
            }
        }

        // (amplitude, millis) ramps within the info's point budget and segment bounds, or null if none follow well.
        private fun fitRamps(pattern: HapticPattern, info: EnvelopeEffectInfo): Pair<List<Pair<Double, Long>>, Fidelity>? {
            var budget = minOf(info.maxControlPoints, EnvelopeControlPoints.MAX_POINTS_LIMIT)
            while (budget >= 1) {
                // The carrier argument is a placeholder: each point's frequency is filled in from the pattern.
                val fitted = EnvelopeControlPoints.fit(
                    pattern.driveEnvelope(), pattern.duration, 1.0, budget, info.minControlPointMillis.toInt(),
                )
                if (!fitted.isRepresentable) return null
                val ramps = ArrayList<Pair<Double, Long>>()
                var previous = 0.0
                for (point in fitted.points) {
                    val parts = ceil(point.durationMillis.toDouble() / info.maxControlPointMillis).toLong()
                    for (k in 1..parts) {
                        // Cut on the same straight line; integer millis that add up to the whole.
                        val millis = point.durationMillis * k / parts - point.durationMillis * (k - 1) / parts
                        // The last part takes the point's own amplitude: p + (0 − p)·3/3 is 1.1e-16 for p = 0.7, and
                        // BasicEnvelopeBuilder refuses an effect that does not end on exactly zero intensity.
                        val amplitude = if (k == parts) point.amplitude else previous + (point.amplitude - previous) * k / parts
                        ramps += amplitude to millis
                    }
                    previous = point.amplitude
                }
                if (ramps.any { it.second < info.minControlPointMillis }) return null
                if (ramps.size <= info.maxControlPoints) return ramps to fitted.fidelity
                budget -= ramps.size - info.maxControlPoints
            }
            return null
        }
    }
}
