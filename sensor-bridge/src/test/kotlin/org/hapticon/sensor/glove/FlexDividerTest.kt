package org.hapticon.sensor.glove

import kotlin.math.ln
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

class FlexDividerTest {
    private fun kiloohms(reading: DividerReading): Double = (reading as DividerReading.Resistance).kiloohms

    @Test
    fun resistanceOf_halfTheSupply_isTheFixedResistor() {
        // Vout = Vin/2 means R = Rfix.
        assertEquals(33.0, kiloohms(FlexDivider().resistanceOf(2.5)), 0.0)
    }

    @Test
    fun papersPrinted22Ohms_givesAbout5MillivoltsOver90Degrees_oneCountOfATenBitAdc() {
        // 002_12aacdd60a14fec1.txt:62 prints Rfix = 22 Ω; Table 1's mean thumb (:259-260) is 16.17 kΩ at 0°,
        // 16.17·e^(0.016·90) = 68.25 kΩ at 90°: Vout = 5·16.17/16.192 = 4.99321 V and 5·68.25/68.27 = 4.99839 V.
        val printed = FlexDivider(fixedKiloohms = FlexDivider.PAPER_PRINTED_FIXED_KILOOHMS)
        val thumb = FlexCalibration.THUMB_DEFAULT
        assertEquals(4.993206521739131, printed.voltsFor(thumb.resistanceAt(0.0)), 1e-12)
        assertEquals(4.998388765921997, printed.voltsFor(thumb.resistanceAt(90.0)), 1e-12)
        val swing = printed.swingVolts(thumb)
        assertEquals(0.005182244182866, swing, 1e-12)
        // One 10-bit count is 5/1023 V = 4.89 mV: the whole 90° bend moves the reading by 1.06 counts.
        assertEquals(1.06, swing / AdcScale.TEN_BIT.voltsOf(1), 0.005)
        // Ours: 1.726 V, 353 counts, 0.25° a count; the paper's value read as 22 kΩ: 1.663 V.
        assertEquals(1.7260533615755, FlexDivider().swingVolts(thumb), 1e-12)
        assertEquals(353.15, FlexDivider().swingVolts(thumb) / AdcScale.TEN_BIT.voltsOf(1), 0.01)
        assertEquals(1.6629896015083, FlexDivider(fixedKiloohms = FlexDivider.PAPER_READ_AS_KILOOHMS).swingVolts(thumb), 1e-12)
    }

    @Test
    fun default33Kiloohms_isTheE6ValueNearestTheWidestSwingForThePapersMeanThumb() {
        val thumb = FlexCalibration.THUMB_DEFAULT
        val widest = FlexDivider.widestSwingKiloohms(thumb.resistanceAt(0.0), thumb.resistanceAt(90.0))
        assertEquals(33.220185016111664, widest, 1e-9)
        // The swing peaks there: 1 % either side swings less, and 33 kΩ is within 0.01 % of the peak.
        val peak = FlexDivider(fixedKiloohms = widest).swingVolts(thumb)
        assertTrue(FlexDivider(fixedKiloohms = widest * 0.99).swingVolts(thumb) < peak)
        assertTrue(FlexDivider(fixedKiloohms = widest * 1.01).swingVolts(thumb) < peak)
        assertEquals(peak, FlexDivider().swingVolts(thumb), peak * 1e-4)
        assertEquals(33.0, FlexDivider.DEFAULT_FIXED_KILOOHMS, 0.0)
    }

    @Test
    fun resistanceOf_oneVoltOnFive_isAQuarterOfTheFixedResistor() {
        // R = 1/(5 − 1)·10 = 2.5 kΩ.
        assertEquals(2.5, kiloohms(FlexDivider(fixedKiloohms = 10.0).resistanceOf(1.0)), 1e-15)
    }

    @Test
    fun resistanceOf_atOrBelowZeroVolts_isAShortCircuitFault() {
        val divider = FlexDivider()
        assertEquals(DividerReading.Fault(SensorFault.SHORT_CIRCUIT, 0.0), divider.resistanceOf(0.0))
        assertEquals(DividerReading.Fault(SensorFault.SHORT_CIRCUIT, -0.1), divider.resistanceOf(-0.1))
        assertEquals(SensorFault.SHORT_CIRCUIT, (divider.resistanceOf(Double.NEGATIVE_INFINITY) as DividerReading.Fault).fault)
    }

    @Test
    fun resistanceOf_atOrAboveTheSupply_isAnOpenCircuitFault() {
        val divider = FlexDivider()
        assertEquals(DividerReading.Fault(SensorFault.OPEN_CIRCUIT, 5.0), divider.resistanceOf(5.0))
        assertEquals(DividerReading.Fault(SensorFault.OPEN_CIRCUIT, 5.1), divider.resistanceOf(5.1))
        assertEquals(SensorFault.OPEN_CIRCUIT, (divider.resistanceOf(Double.POSITIVE_INFINITY) as DividerReading.Fault).fault)
    }

    @Test
    fun resistanceOf_nan_isANotANumberFault() {
        assertEquals(SensorFault.NOT_A_NUMBER, (FlexDivider().resistanceOf(Double.NaN) as DividerReading.Fault).fault)
    }

    @Test
    fun resistanceOf_oneUlpBelowTheSupply_isFiniteAndHuge() {
        val r = kiloohms(FlexDivider(fixedKiloohms = FlexDivider.MAX_FIXED_KILOOHMS).resistanceOf(Math.nextDown(5.0)))
        // 5/ulp(5)·1e6 ≈ 5.6e21 kΩ: absurd but finite, and it saturates every angle downstream.
        assertTrue(r.isFinite())
        assertTrue(r > 5e21)
    }

    @Test
    fun resistanceOf_aVoltageSoSmallThatRUnderflows_isAShortCircuitNotZeroKiloohms() {
        // 4.9e-324/5·33 rounds to 0: a resistance of 0 would give ln R = −∞ in the calibration.
        assertEquals(DividerReading.Fault(SensorFault.SHORT_CIRCUIT, Double.MIN_VALUE), FlexDivider().resistanceOf(Double.MIN_VALUE))
        assertTrue(kiloohms(FlexDivider().resistanceOf(1e-300)) > 0.0)
    }

    @Test
    fun voltsFor_isTheInverseOfResistanceOf() {
        val divider = FlexDivider(fixedKiloohms = 20.0)
        // 5·60/(60 + 20) = 3.75 V, and back.
        assertEquals(3.75, divider.voltsFor(60.0), 1e-15)
        assertEquals(60.0, kiloohms(divider.resistanceOf(3.75)), 1e-12)
    }

    @Test
    fun constructor_nonPositiveOrNonFiniteParts_areRejected() {
        assertThrows(IllegalArgumentException::class.java) { FlexDivider(fixedKiloohms = 0.0) }
        assertThrows(IllegalArgumentException::class.java) { FlexDivider(fixedKiloohms = Double.NaN) }
        assertThrows(IllegalArgumentException::class.java) { FlexDivider(fixedKiloohms = Math.nextUp(FlexDivider.MAX_FIXED_KILOOHMS)) }
        assertThrows(IllegalArgumentException::class.java) { FlexDivider(supplyVolts = 0.0) }
        assertThrows(IllegalArgumentException::class.java) { FlexDivider(supplyVolts = Double.POSITIVE_INFINITY) }
    }

    @Test
    fun adcScale_tenAndTwelveBits_mapFullScaleToTheReference() {
        assertEquals(1023, AdcScale.TEN_BIT.fullScale)
        assertEquals(4095, AdcScale.TWELVE_BIT.fullScale)
        assertEquals(5.0, AdcScale.TEN_BIT.voltsOf(1023), 0.0)
        assertEquals(0.0, AdcScale.TEN_BIT.voltsOf(0), 0.0)
        assertEquals(2.5024437927663734, AdcScale.TEN_BIT.voltsOf(512), 1e-15)
        assertEquals(3.3, AdcScale(12, 3.3).voltsOf(4095), 0.0)
        assertEquals(1.6504029304029304, AdcScale(12, 3.3).voltsOf(2048), 1e-15)
    }

    @Test
    fun adcScale_countsOutsideTheRangeOrBadBits_areRejected() {
        assertThrows(IllegalArgumentException::class.java) { AdcScale.TEN_BIT.voltsOf(1024) }
        assertThrows(IllegalArgumentException::class.java) { AdcScale.TEN_BIT.voltsOf(-1) }
        assertThrows(IllegalArgumentException::class.java) { AdcScale(7) }
        assertThrows(IllegalArgumentException::class.java) { AdcScale(17) }
        assertThrows(IllegalArgumentException::class.java) { AdcScale(10, 0.0) }
    }

    @Test
    fun channel_countsTwiceTheRemainder_givesLnTwoOverAlpha() {
        // With Rfix = β, R/β = c/(1023 − c) = 682/341 = 2, so θ = ln 2/α.
        val channel = FlexSensorChannel(FlexCalibration.MIDDLE_DEFAULT, FlexDivider(fixedKiloohms = 16.24))
        val angle = channel.angleOfCounts(682) as AngleReading.Angle
        assertEquals(ln(2.0) / 0.019, angle.degrees, 1e-9)
        assertEquals(36.4814306, angle.degrees, 1e-6)
    }

    @Test
    fun channel_saturatedZeroOrInvalidCounts_areFaultsNotAngles() {
        val channel = FlexSensorChannel(FlexCalibration.THUMB_DEFAULT)
        assertEquals(AngleReading.Fault(SensorFault.OPEN_CIRCUIT), channel.angleOfCounts(1023))
        assertEquals(AngleReading.Fault(SensorFault.SHORT_CIRCUIT), channel.angleOfCounts(0))
        assertEquals(AngleReading.Fault(SensorFault.COUNT_OUT_OF_RANGE), channel.angleOfCounts(1024))
        assertEquals(AngleReading.Fault(SensorFault.COUNT_OUT_OF_RANGE), channel.angleOfCounts(-1))
        assertEquals(AngleReading.Fault(SensorFault.NOT_A_NUMBER), channel.angleOfVolts(Double.NaN))
    }

    @Test
    fun channel_tenBitQuantisation_staysWithinHalfACountOfTheTrueAngle() {
        // One count at the divider's mid-point moves R by about 4·Rfix/1023 relative, i.e. ≈ 0.2° at α = 0.019.
        val calibration = FlexCalibration.MIDDLE_DEFAULT
        val divider = FlexDivider()
        val channel = FlexSensorChannel(calibration, divider)
        for (degrees in listOf(0.0, 30.0, 60.0, 90.0)) {
            val volts = divider.voltsFor(calibration.resistanceAt(degrees))
            val counts = Math.round(volts / 5.0 * 1023).toInt()
            val measured = (channel.angleOfCounts(counts) as AngleReading.Angle).degrees
            // Bound: half a count in V, through dθ/dV = (1/α)·Vin/(V·(Vin − V)), plus 5 % for the curvature.
            val bound = 1.05 * 0.5 * 5.0 / 1023 / calibration.alphaPerDegree * 5.0 / (volts * (5.0 - volts))
            assertTrue("at $degrees°: $measured", kotlin.math.abs(measured - degrees) <= bound)
        }
    }

    @Test
    fun resistanceOrNaN_isResistanceOfsValueOrNaNForEveryFault() {
        val divider = FlexDivider()
        val inputs = doubleArrayOf(0.001, 1.0, 2.5, 4.999, Double.MIN_VALUE, 0.0, -1.0, 5.0, 7.0, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY)
        for (volts in inputs) {
            val expected = (divider.resistanceOf(volts) as? DividerReading.Resistance)?.kiloohms ?: Double.NaN
            org.junit.Assert.assertEquals("at $volts V", expected, divider.resistanceOrNaN(volts), 0.0)
        }
        // Vout = Vin/2 puts R equal to Rfix.
        org.junit.Assert.assertEquals(divider.fixedKiloohms, divider.resistanceOrNaN(2.5), 1e-12)
    }
}
