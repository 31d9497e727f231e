package org.hapticon.sensor.electrotactile

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class ElectrotactileCalibrationTest {
    @Test
    fun amplitudeSteps_twoHundredStepsOverZeroTo2point7mA() {
        assertEquals(0.0135, AmplitudeSteps.MILLIAMPS_PER_STEP, 1e-15)
        assertEquals(0.0, AmplitudeSteps.milliampsOf(0), 0.0)
        assertEquals(0.81, AmplitudeSteps.milliampsOf(60), 1e-12)
        assertEquals(2.7, AmplitudeSteps.milliampsOf(200), 0.0)
        assertEquals(60, AmplitudeSteps.stepAtLeast(0.8))
        assertEquals(60, AmplitudeSteps.stepAtLeast(0.81))
        assertEquals(200, AmplitudeSteps.stepAtLeast(2.7))
    }

    @Test
    fun amplitudeSteps_justPastTheCapNanOrNegative_isRefused() {
        assertCurrentRefused { AmplitudeSteps.stepAtLeast(Math.nextUp(2.7)) }
        assertCurrentRefused { AmplitudeSteps.stepAtLeast(Double.NaN) }
        assertCurrentRefused { AmplitudeSteps.stepAtLeast(Double.POSITIVE_INFINITY) }
        assertCurrentRefused { AmplitudeSteps.stepAtLeast(-0.01) }
        assertCurrentRefused { AmplitudeSteps.milliampsOf(201) }
        assertCurrentRefused { AmplitudeSteps.milliampsOf(-1) }
    }

    @Test
    fun calibration_eachElectrodeInOrder_thenTheWholeArrayCheck() {
        val calibration = ElectrotactileCalibration()
        for (electrode in 0..8) {
            assertEquals(electrode, calibration.currentElectrode)
            val first = calibration.stimulus()!!
            // A 200 ms stimulus on that electrode alone, starting at 0.81 mA (step 60, the first at or above 0.8 mA).
            assertEquals(CalibrationStimulus(ElectrodePattern(1 shl electrode), listOf(60), 200, 0), first)
            repeat(electrode) { calibration.notYet() }
            assertEquals(listOf(60 + electrode), calibration.stimulus()!!.steps)
            calibration.clearAndPainFree()
        }
        assertTrue(calibration.isCheckingWholeArray)
        val check = calibration.stimulus()!!
        assertEquals(ElectrodePattern.ALL, check.electrodes)
        assertEquals(39, check.grains)
        assertEquals((60..68).toList(), check.steps)
        calibration.tooStrong()
        assertEquals((59..67).toList(), calibration.stimulus()!!.steps)
        calibration.wholeArrayOk()
        assertTrue(calibration.isDone)
        assertNull(calibration.stimulus())
        val result = calibration.result()
        assertEquals((59..67).toList(), result.steps)
        assertEquals(67 * 0.0135, result.userLimit().maxMilliamps, 1e-12)
    }

    @Test
    fun wholeArrayCheck_oneElectrodeAdjusted_forAUniformSensation() {
        val calibration = ElectrotactileCalibration()
        repeat(9) { calibration.clearAndPainFree() }
        // The person feels electrode 5 stand out and electrode 1 faint (003_8ca1dc8f53472543.txt:152: "uniform").
        calibration.weaker(4)
        calibration.weaker(4)
        calibration.stronger(0)
        assertEquals(listOf(61, 60, 60, 60, 58, 60, 60, 60, 60), calibration.stimulus()!!.steps)
        calibration.tooStrong()
        assertEquals(listOf(60, 59, 59, 59, 57, 59, 59, 59, 59), calibration.stimulus()!!.steps)
        calibration.wholeArrayOk()
        assertEquals(listOf(60, 59, 59, 59, 57, 59, 59, 59, 59), calibration.result().steps)
    }

    @Test
    fun wholeArrayCheck_adjustments_stopAtTheCapAndZero_andOnlyInTheCheck() {
        val calibration = ElectrotactileCalibration()
        try {
            calibration.weaker(0)
            fail("accepted before the check")
        } catch (_: IllegalStateException) {
        }
        repeat(9) { calibration.clearAndPainFree() }
        repeat(300) { calibration.stronger(8) }
        repeat(100) { calibration.weaker(0) }
        assertEquals(200, calibration.steps()[8])
        assertEquals(0, calibration.steps()[0])
        try {
            calibration.stronger(9)
            fail("accepted electrode 9")
        } catch (e: IllegalArgumentException) {
            assertEquals("electrode must be in 0..8, was 9", e.message)
        }
    }

    @Test
    fun calibration_raisingPastTheCap_staysAt2point7mA() {
        val calibration = ElectrotactileCalibration()
        repeat(500) { calibration.notYet() }
        assertEquals(listOf(200), calibration.stimulus()!!.steps)
        assertEquals(2.7, AmplitudeSteps.milliampsOf(calibration.stimulus()!!.steps.single()), 0.0)
    }

    @Test
    fun calibration_outOfOrderActions_areRejected() {
        val calibration = ElectrotactileCalibration()
        try {
            calibration.wholeArrayOk()
            fail("accepted")
        } catch (_: IllegalStateException) {
        }
        repeat(9) { calibration.clearAndPainFree() }
        try {
            calibration.notYet()
            fail("accepted")
        } catch (_: IllegalStateException) {
        }
        assertFalse(calibration.isDone)
    }

    @Test
    fun result_stepPastTheCap_isRefused() {
        assertCurrentRefused { ElectrotactileCalibrationResult(List(8) { 60 } + 201) }
    }

    @Test
    fun scan_largeSquare_pulsesEachElectrode250MicrosApartTwicePerGrain() {
        val pulses = TimeDivisionScan.schedule(ElectrodeMask.LARGE_SQUARE.pattern)
        assertEquals(18, pulses.size)
        // 200 µs pulse + 50 µs gap per electrode (4 kHz), the second pulse of the 125 Hz train 8 ms later.
        assertEquals((0..8).map { ScanPulse(it, 250L * it) } + (0..8).map { ScanPulse(it, 8000 + 250L * it) }, pulses)
        assertEquals(4000.0, TimeDivisionScan.SCAN_HZ, 0.0)
    }

    @Test
    fun scan_smallSquare_skipsTheElectrodesOff() {
        assertEquals(
            listOf(ScanPulse(0, 0), ScanPulse(1, 250), ScanPulse(3, 500), ScanPulse(4, 750)),
            TimeDivisionScan.schedule(ElectrodeMask.SMALL_SQUARE.pattern).take(4),
        )
    }

    @Test
    fun scan_tooManyElectrodesForThePeriod_isRejected() {
        try {
            // Nine 250 µs slots = 2.25 ms do not fit in a 1 ms period.
            TimeDivisionScan.schedule(ElectrodePattern.ALL, PulseTrain(frequencyHz = 1000.0))
            fail("accepted")
        } catch (_: IllegalArgumentException) {
        }
    }
}
