package org.hapticon.sensor.glove

import kotlin.math.exp
import kotlin.math.ln
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class FlexCalibrationTest {
    private fun fitted(points: List<CalibrationPoint>): FlexFit = (FlexCalibration.fit(points) as FitResult.Fitted).fit

    private fun rejection(points: List<CalibrationPoint>): String = (FlexCalibration.fit(points) as FitResult.Rejected).reason

    @Test
    fun defaults_areTheStudyMeans() {
        assertEquals(FlexCalibration(0.016, 16.17), FlexCalibration.THUMB_DEFAULT)
        assertEquals(FlexCalibration(0.019, 16.24), FlexCalibration.MIDDLE_DEFAULT)
        assertEquals(FlexCalibration.THUMB_DEFAULT, FlexCalibration.defaultFor(GloveFinger.THUMB))
        assertEquals(FlexCalibration.MIDDLE_DEFAULT, FlexCalibration.defaultFor(GloveFinger.MIDDLE))
    }

    @Test
    fun resistanceAt_zeroAndFiftyDegrees_isBetaAndBetaTimesEToAlphaTheta() {
        assertEquals(16.24, FlexCalibration.MIDDLE_DEFAULT.resistanceAt(0.0), 0.0)
        // 16.24·e^(0.019·50) = 16.24·e^0.95.
        assertEquals(41.991924867289335, FlexCalibration.MIDDLE_DEFAULT.resistanceAt(50.0), 1e-12)
    }

    @Test
    fun angleOf_twiceBeta_isLnTwoOverAlpha() {
        assertEquals(ln(2.0) / 0.016, FlexCalibration.THUMB_DEFAULT.angleOf(2 * 16.17), 1e-12)
        assertEquals(43.32170, FlexCalibration.THUMB_DEFAULT.angleOf(2 * 16.17), 1e-5)
    }

    @Test
    fun angleOf_belowBeta_isNegative() {
        // Half of β is −ln 2/α: straighter than the calibration's 0°.
        assertEquals(-ln(2.0) / 0.019, FlexCalibration.MIDDLE_DEFAULT.angleOf(8.12), 1e-12)
    }

    @Test
    fun angleOf_nonPositiveOrNonFiniteResistance_isRejected() {
        for (bad in listOf(0.0, -1.0, Double.NaN, Double.POSITIVE_INFINITY)) {
            assertThrows(IllegalArgumentException::class.java) { FlexCalibration.THUMB_DEFAULT.angleOf(bad) }
        }
    }

    @Test
    fun constructor_nonPositiveOrNonFiniteParameters_areRejected() {
        assertThrows(IllegalArgumentException::class.java) { FlexCalibration(0.0, 16.0) }
        assertThrows(IllegalArgumentException::class.java) { FlexCalibration(-0.01, 16.0) }
        assertThrows(IllegalArgumentException::class.java) { FlexCalibration(Double.NaN, 16.0) }
        assertThrows(IllegalArgumentException::class.java) { FlexCalibration(0.01, 0.0) }
        assertThrows(IllegalArgumentException::class.java) { FlexCalibration(0.01, Double.POSITIVE_INFINITY) }
    }

    @Test
    fun fit_exactExponentialAtTheFivePoses_recoversAlphaAndBeta() {
        val points = listOf(0.0, 30.0, 50.0, 70.0, 90.0).map { CalibrationPoint(it, 20.0 * exp(0.02 * it)) }
        val fit = fitted(points)
        assertEquals(0.02, fit.calibration.alphaPerDegree, 1e-14)
        assertEquals(20.0, fit.calibration.betaKiloohms, 1e-12)
        assertEquals(1.0, fit.rSquared, 1e-12)
        fit.logResiduals.forEach { assertEquals(0.0, it, 1e-13) }
        assertEquals(0.0, fit.rmsAngleErrorDegrees, 1e-10)
    }

    @Test
    fun fit_twoPoints_passesThroughBoth() {
        // ln R from ln 10 to ln 10 + 1 over 50°: α = 1/50.
        val fit = fitted(listOf(CalibrationPoint(0.0, 10.0), CalibrationPoint(50.0, 10.0 * exp(1.0))))
        assertEquals(0.02, fit.calibration.alphaPerDegree, 1e-15)
        assertEquals(10.0, fit.calibration.betaKiloohms, 1e-12)
    }

    @Test
    fun fit_threeNoisyPoints_matchesTheHandComputedRegression() {
        // θ = 0, 10, 20 and ln R = 0, 1.2, 1.8: θ̄ = 10, ȳ = 1, Sxy = 18, Sxx = 200 → α = 0.09, ln β = 0.1.
        // Residuals −0.1, 0.2, −0.1; SSres = 0.06, SStot = 1.68 → R² = 1 − 0.06/1.68.
        val fit = fitted(listOf(CalibrationPoint(0.0, 1.0), CalibrationPoint(10.0, exp(1.2)), CalibrationPoint(20.0, exp(1.8))))
        assertEquals(0.09, fit.calibration.alphaPerDegree, 1e-15)
        assertEquals(1.1051709180756477, fit.calibration.betaKiloohms, 1e-14)
        assertEquals(0.9642857142857143, fit.rSquared, 1e-14)
        assertEquals(listOf(-0.1, 0.2, -0.1), fit.logResiduals.map { Math.round(it * 1e12) / 1e12 })
        // Angle errors are residual/α: −1.11…, 2.22…, −1.11… degrees.
        assertEquals(-1.0 / 0.9, fit.angleErrorsDegrees[0], 1e-12)
        assertEquals(2.0 / 0.9, fit.angleErrorsDegrees[1], 1e-12)
        assertEquals(-1.0 / 0.9, fit.angleErrorsDegrees[2], 1e-12)
        // √(0.06/3)/0.09.
        assertEquals(1.5713484026367723, fit.rmsAngleErrorDegrees, 1e-12)
    }

    @Test
    fun fit_fewerThanTwoDistinctAngles_isRejected() {
        assertEquals("need at least 2 distinct angles, got 0", rejection(emptyList()))
        assertEquals("need at least 2 distinct angles, got 1", rejection(listOf(CalibrationPoint(30.0, 20.0))))
        assertEquals(
            "need at least 2 distinct angles, got 1",
            rejection(listOf(CalibrationPoint(30.0, 20.0), CalibrationPoint(30.0, 25.0))),
        )
    }

    @Test
    fun fit_nonPositiveOrNonFiniteResistance_isRejectedNamingThePoint() {
        assertEquals(
            "point 1: resistance must be finite and > 0 kΩ, was 0.0",
            rejection(listOf(CalibrationPoint(0.0, 16.0), CalibrationPoint(30.0, 0.0))),
        )
        assertEquals(
            "point 0: resistance must be finite and > 0 kΩ, was -5.0",
            rejection(listOf(CalibrationPoint(0.0, -5.0), CalibrationPoint(30.0, 20.0))),
        )
        assertEquals(
            "point 1: resistance must be finite and > 0 kΩ, was NaN",
            rejection(listOf(CalibrationPoint(0.0, 16.0), CalibrationPoint(30.0, Double.NaN))),
        )
        assertEquals(
            "point 1: angle must be finite, was Infinity",
            rejection(listOf(CalibrationPoint(0.0, 16.0), CalibrationPoint(Double.POSITIVE_INFINITY, 20.0))),
        )
    }

    @Test
    fun fit_resistanceThatFallsOrStaysFlat_isRejected() {
        assertEquals(
            "fitted α = 0.0 per degree: the resistance does not rise with bending",
            rejection(listOf(CalibrationPoint(0.0, 20.0), CalibrationPoint(90.0, 20.0))),
        )
        val falling = rejection(listOf(CalibrationPoint(0.0, 20.0), CalibrationPoint(90.0, 10.0)))
        org.junit.Assert.assertTrue(falling.endsWith("the resistance does not rise with bending"))
    }
}
