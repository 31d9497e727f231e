package org.hapticon.sensor.glove

import kotlin.math.exp
import kotlin.math.ln
import kotlin.math.sqrt

/** A finger that carries a flex sensor on the tele-handshake glove. */
public enum class GloveFinger {
    /** The thumb: no handshake threshold, contributes nT to the pressure. */
    THUMB,

    /** The middle finger: starts the handshake above 30.9°, contributes nM to the pressure. */
    MIDDLE,
}

/**
 * One finger's flex-sensor calibration, ln R = α·θ + ln β, the tele-handshake paper's Eq. 5
 * (002_12aacdd60a14fec1.txt:85): the resistance R (kΩ) rises exponentially with the bend angle θ (degrees).
 * [alphaPerDegree] is α in 1/°, [betaKiloohms] is β, the resistance at 0°, in kΩ (Table 1 gives β = 16.17 and
 * 16.24 without a unit, :259-262; kΩ matches a flex sensor's flat resistance, so that is the unit assumed here and
 * everywhere in the glove model; see [FlexDivider.PAPER_PRINTED_FIXED_KILOOHMS]).
 *
 * Both must be finite and > 0: a sensor whose resistance does not rise with bending cannot be inverted.
 */
public data class FlexCalibration(val alphaPerDegree: Double, val betaKiloohms: Double) {
    init {
        require(alphaPerDegree > 0.0 && alphaPerDegree.isFinite()) {
            "alphaPerDegree must be finite and > 0 (resistance must rise with bending), was $alphaPerDegree"
        }
        require(betaKiloohms > 0.0 && betaKiloohms.isFinite()) { "betaKiloohms must be finite and > 0, was $betaKiloohms" }
    }

    /** The resistance at [degrees]: β·e^(α·θ), in kΩ. */
    public fun resistanceAt(degrees: Double): Double = betaKiloohms * exp(alphaPerDegree * degrees)

    /**
     * The bend angle for a resistance of [kiloohms]: θ = (ln R − ln β)/α, in degrees. Resistances below β
     * give negative angles (the finger is straighter than at calibration's 0°); downstream models clamp.
     * @throws IllegalArgumentException when [kiloohms] is not finite and > 0 (use [DividerReading] first).
     */
    public fun angleOf(kiloohms: Double): Double {
        require(kiloohms > 0.0 && kiloohms.isFinite()) { "kiloohms must be finite and > 0, was $kiloohms" }
        return (ln(kiloohms) - ln(betaKiloohms)) / alphaPerDegree
    }

    public companion object {
        /** Table 1's mean thumb calibration over its six participants: α 0.016/°, β 16.17 kΩ (002_12aacdd60a14fec1.txt:259-260). */
        public val THUMB_DEFAULT: FlexCalibration = FlexCalibration(0.016, 16.17)

        /** Table 1's mean middle-finger calibration: α 0.019/°, β 16.24 kΩ (002_12aacdd60a14fec1.txt:261-262). */
        public val MIDDLE_DEFAULT: FlexCalibration = FlexCalibration(0.019, 16.24)

        /** The study's mean calibration for [finger]. */
        public fun defaultFor(finger: GloveFinger): FlexCalibration = when (finger) {
            GloveFinger.THUMB -> THUMB_DEFAULT
            GloveFinger.MIDDLE -> MIDDLE_DEFAULT
        }

        /**
         * Fits ln R = α·θ + ln β to [points] by ordinary least squares on (θ, ln R), as the paper determined α and
         * β ("the least squares method", 002_12aacdd60a14fec1.txt:84):
         * α = Σ(θ − θ̄)(y − ȳ)/Σ(θ − θ̄)², ln β = ȳ − α·θ̄ with y = ln R.
         *
         * Returns [FitResult.Rejected] (never throws) when the input is degenerate: fewer than 2 distinct
         * angles, a non-finite angle, a resistance that is not finite and > 0, or a fitted α ≤ 0 (the
         * resistance does not rise with bending: the sensor is not responding or is mounted wrongly).
         */
        public fun fit(points: List<CalibrationPoint>): FitResult {
            points.forEachIndexed { i, point ->
                if (!point.degrees.isFinite()) return FitResult.Rejected("point $i: angle must be finite, was ${point.degrees}")
                if (!(point.kiloohms > 0.0 && point.kiloohms.isFinite())) {
                    return FitResult.Rejected("point $i: resistance must be finite and > 0 kΩ, was ${point.kiloohms}")
                }
            }
            val distinctAngles = points.map { it.degrees }.distinct().size
            if (distinctAngles < 2) return FitResult.Rejected("need at least 2 distinct angles, got $distinctAngles")

            val n = points.size
            val meanAngle = points.sumOf { it.degrees } / n
            val meanLog = points.sumOf { ln(it.kiloohms) } / n
            var sxy = 0.0
            var sxx = 0.0
            var syy = 0.0
            for (point in points) {
                val dx = point.degrees - meanAngle
                val dy = ln(point.kiloohms) - meanLog
                sxy += dx * dy
                sxx += dx * dx
                syy += dy * dy
            }
            val alpha = sxy / sxx
            if (!(alpha > 0.0 && alpha.isFinite())) {
                return FitResult.Rejected("fitted α = $alpha per degree: the resistance does not rise with bending")
            }
            val logBeta = meanLog - alpha * meanAngle
            val calibration = FlexCalibration(alpha, exp(logBeta))
            val residuals = points.map { ln(it.kiloohms) - (alpha * it.degrees + logBeta) }
            val residualSquares = residuals.sumOf { it * it }
            // syy > 0 here because α > 0 needs ln R to vary.
            val rSquared = 1.0 - residualSquares / syy
            return FitResult.Fitted(
                FlexFit(
                    calibration = calibration,
                    rSquared = rSquared,
                    logResiduals = residuals,
                    angleErrorsDegrees = points.map { calibration.angleOf(it.kiloohms) - it.degrees },
                    rmsAngleErrorDegrees = sqrt(residualSquares / n) / alpha,
                ),
            )
        }
    }
}

/** A calibration sample: the finger held at [degrees] read [kiloohms]. */
public data class CalibrationPoint(val degrees: Double, val kiloohms: Double)

/**
 * A least-squares calibration and its quality: [rSquared] in ln R (1 = perfect), [logResiduals] are
 * ln Rᵢ − (α·θᵢ + ln β) per point, [angleErrorsDegrees] are θ(Rᵢ) − θᵢ (the angle error the fitted
 * calibration would make at each pose, = residual/α), and [rmsAngleErrorDegrees] their RMS.
 */
public data class FlexFit(
    val calibration: FlexCalibration,
    val rSquared: Double,
    val logResiduals: List<Double>,
    val angleErrorsDegrees: List<Double>,
    val rmsAngleErrorDegrees: Double,
)

/** The outcome of [FlexCalibration.fit]. */
public sealed interface FitResult {
    /** The points gave a usable calibration. */
    public data class Fitted(val fit: FlexFit) : FitResult

    /** The points cannot be fitted; [reason] says why, for the person calibrating. */
    public data class Rejected(val reason: String) : FitResult
}
