package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import java.util.Locale
import kotlin.math.abs
import kotlin.math.ceil
import kotlin.math.floor
import kotlin.math.sqrt

// The walk shared by the vibrator renderers (VibrationWaveform and EnvelopeControlPoints): both read an icon's
// ideal envelope the same way and measure against the same finely sampled cells, so their Fidelity numbers are
// comparable.

/**
 * [HapticIcon.envelope] under [model] at Processing's 44100 Hz as a function of time: the ideal envelope the
 * vibrator renderers approximate.
 */
internal fun HapticIcon.idealEnvelope(model: EnvelopeModel): (Double) -> Double = envelope(model)::sample

/**
 * The ideal [envelope] over [durationSeconds] (rounded to [totalMillis]) sampled on 0.1 ms [cells] ([sampleCells]),
 * and the errors of an approximation against them ([errorsOf]).
 */
internal class EnvelopeCells(
    envelope: (Double) -> Double,
    durationSeconds: Double,
    val totalMillis: Int = totalMillisOf(durationSeconds),
) {
    val cells: DoubleArray = sampleCells(envelope, durationSeconds, totalMillis)

    /** [measureErrors] of [approximation] (a value per cell index) against [cells]. */
    inline fun errorsOf(approximation: (cell: Int) -> Double): EnvelopeErrors = measureErrors(cells, approximation)
}

/** The ideal envelope is sampled at the centres of cells this many to a millisecond (10 kHz). */
internal const val CELLS_PER_MILLI: Int = 10

/** An amplitude below half of one 1/255 step rounds to zero: the vibrator is off there. */
internal const val OFF_BELOW: Double = 0.5 / 255

/**
 * round([x]) with ties up. The 1e-9 nudge keeps exact ties (x.5, common with linear ramps) from rounding
 * down when floating-point noise lands a hair below them, so results are predictable.
 */
internal fun roundHalfUp(x: Double): Long = floor(x + 0.5 + 1e-9).toLong()

/**
 * [durationSeconds] rounded to whole milliseconds. Throws [IllegalArgumentException] when it is not finite,
 * rounds to 0 ms (nothing to play) or exceeds the [HapticIcon.MAX_DURATION_SECONDS] safety cap.
 */
internal fun totalMillisOf(durationSeconds: Double): Int {
    require(durationSeconds.isFinite() && durationSeconds >= 0.0) { "duration must be finite and >= 0, was $durationSeconds" }
    val millis = roundHalfUp(durationSeconds * 1000.0)
    val capMillis = roundHalfUp(HapticIcon.MAX_DURATION_SECONDS * 1000.0)
    require(millis <= capMillis) {
        "duration $durationSeconds s exceeds the ${HapticIcon.MAX_DURATION_SECONDS} s safety cap"
    }
    require(millis > 0) { "duration $durationSeconds s rounds to 0 ms: nothing to play" }
    return millis.toInt()
}

/** [value] clamped to [0, 1], NaN read as 0: a broken envelope must not drive the actuator harder. */
internal fun safeAmplitude(value: Double): Double = if (value.isNaN()) 0.0 else value.coerceIn(0.0, 1.0)

/**
 * The ideal envelope at the centre of every cell covering [0, max(durationSeconds, totalMillis)], so the
 * comparison also sees any ideal tail cut off by rounding the duration down to whole milliseconds.
 */
internal fun sampleCells(envelope: (Double) -> Double, durationSeconds: Double, totalMillis: Int): DoubleArray {
    val spanMillis = maxOf(totalMillis, ceil(durationSeconds * 1000.0 - 1e-9).toInt())
    return DoubleArray(spanMillis * CELLS_PER_MILLI) { cell ->
        safeAmplitude(envelope((cell + 0.5) / (1000.0 * CELLS_PER_MILLI)))
    }
}

/** RMS and largest error of an approximation against the ideal cells, and the RMS relative to the ideal's RMS. */
internal class EnvelopeErrors(val rms: Double, val max: Double, val relativeRms: Double) {
    /** For Fidelity descriptions, for example "RMS error 0.0123 (4.5% of the envelope RMS)". */
    fun summary(): String {
        val relative = if (relativeRms.isInfinite()) "∞" else String.format(Locale.ROOT, "%.1f", relativeRms * 100)
        return String.format(Locale.ROOT, "RMS error %.4f (%s%% of the envelope RMS), max error %.4f", rms, relative, max)
    }
}

/** Compares [approximation] (value for a cell index) with [ideal] cell by cell. */
internal inline fun measureErrors(ideal: DoubleArray, approximation: (cell: Int) -> Double): EnvelopeErrors {
    var squaredError = 0.0
    var squaredIdeal = 0.0
    var maxError = 0.0
    for (cell in ideal.indices) {
        val error = abs(approximation(cell) - ideal[cell])
        squaredError += error * error
        squaredIdeal += ideal[cell] * ideal[cell]
        maxError = maxOf(maxError, error)
    }
    if (ideal.isEmpty()) return EnvelopeErrors(0.0, 0.0, 0.0)
    val relative = when {
        squaredError == 0.0 -> 0.0
        squaredIdeal == 0.0 -> Double.POSITIVE_INFINITY
        else -> sqrt(squaredError / squaredIdeal)
    }
    return EnvelopeErrors(sqrt(squaredError / ideal.size), maxError, relative)
}
