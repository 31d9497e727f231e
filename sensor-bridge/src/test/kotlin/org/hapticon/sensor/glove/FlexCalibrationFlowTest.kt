package org.hapticon.sensor.glove

import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import kotlin.math.exp

class FlexCalibrationFlowTest {
    private fun r(kiloohms: Double): DividerReading = DividerReading.Resistance(kiloohms)

    private fun flow(poses: List<Double> = FlexCalibrationFlow.DEFAULT_POSES_DEGREES, takes: Int = 1) =
        FlexCalibrationFlow(GloveFinger.MIDDLE, poses, SettleCriterion(windowSamples = 3, maxRelativeSpread = 0.02), takes)

    /** Holds the current pose steady at [kiloohms] for a full window. */
    private fun hold(flow: FlexCalibrationFlow, kiloohms: Double): CalibrationState {
        flow.beginPose()
        repeat(2) { flow.offer(r(kiloohms)) }
        return flow.offer(r(kiloohms))
    }

    @Test
    fun newFlow_waitsForTheFirstPoseAtZeroDegrees() {
        assertEquals(CalibrationState.WaitingForPose(0, 0.0), flow().state)
    }

    @Test
    fun offer_whileWaitingForAPose_isIgnored() {
        val flow = flow()
        assertEquals(CalibrationState.WaitingForPose(0, 0.0), flow.offer(r(20.0)))
        assertEquals(emptyList<CalibrationPoint>(), flow.points)
    }

    @Test
    fun offer_aMovingReading_isNotCapturedUntilTheWindowSettles() {
        val flow = flow()
        assertEquals(CalibrationState.Settling(0, 0.0, 0, null, 0), flow.beginPose())
        assertEquals(CalibrationState.Settling(0, 0.0, 1, null, 0), flow.offer(r(10.0)))
        assertEquals(CalibrationState.Settling(0, 0.0, 2, null, 0), flow.offer(r(11.0)))
        // Window 10, 11, 12: spread 2/11 > 2 %.
        assertEquals(CalibrationState.Settling(0, 0.0, 3, 2.0 / 11.0, 0), flow.offer(r(12.0)))
        // Window 11, 12, 20: spread 9/(43/3).
        val moving = flow.offer(r(20.0)) as CalibrationState.Settling
        assertEquals(27.0 / 43.0, moving.relativeSpread!!, 1e-15)
        flow.offer(r(20.0))
        // Window 20, 20, 20: settled; the mean 20 is captured and the flow waits for 30°.
        assertEquals(CalibrationState.WaitingForPose(1, 30.0), flow.offer(r(20.0)))
        assertEquals(listOf(CalibrationPoint(0.0, 20.0)), flow.points)
    }

    @Test
    fun offer_spreadExactlyAtTheCriterion_settles() {
        val flow = flow()
        flow.beginPose()
        flow.offer(r(99.0))
        flow.offer(r(100.0))
        // (101 − 99)/100 = 0.02: at the limit counts as settled, and the mean is 100.
        assertEquals(CalibrationState.WaitingForPose(1, 30.0), flow.offer(r(101.0)))
        assertEquals(listOf(CalibrationPoint(0.0, 100.0)), flow.points)
    }

    @Test
    fun offer_spreadJustAboveTheCriterion_keepsSettling() {
        val flow = flow()
        flow.beginPose()
        flow.offer(r(98.9))
        flow.offer(r(100.0))
        val state = flow.offer(r(101.1)) as CalibrationState.Settling
        assertEquals(2.2 / 100.0, state.relativeSpread!!, 1e-12)
        assertEquals(emptyList<CalibrationPoint>(), flow.points)
    }

    @Test
    fun offer_aFault_emptiesTheWindowAndIsCounted() {
        val flow = flow()
        flow.beginPose()
        flow.offer(r(20.0))
        flow.offer(r(20.0))
        assertEquals(
            CalibrationState.Settling(0, 0.0, 0, null, 1),
            flow.offer(DividerReading.Fault(SensorFault.OPEN_CIRCUIT, 5.0)),
        )
        flow.offer(r(20.0))
        assertEquals(CalibrationState.Settling(0, 0.0, 2, null, 1), flow.offer(r(20.0)))
        assertEquals(CalibrationState.WaitingForPose(1, 30.0), flow.offer(r(20.0)))
    }

    @Test
    fun allFivePoses_onAnExactExponential_endCalibratedWithItsParameters() {
        val flow = flow()
        for (pose in FlexCalibrationFlow.DEFAULT_POSES_DEGREES) hold(flow, 20.0 * exp(0.02 * pose))
        val fit = (flow.state as CalibrationState.Calibrated).fit
        assertEquals(0.02, fit.calibration.alphaPerDegree, 1e-12)
        assertEquals(20.0, fit.calibration.betaKiloohms, 1e-10)
        assertEquals(listOf(0.0, 30.0, 50.0, 70.0, 90.0), flow.points.map { it.degrees })
    }

    @Test
    fun defaultFlow_takesEachPoseTwice_roundByRound() {
        assertEquals(2, FlexCalibrationFlow(GloveFinger.THUMB).takesPerPose)
        assertEquals(10, FlexCalibrationFlow(GloveFinger.THUMB).totalTakes)
    }

    @Test
    fun twoTakes_walkThePosesTwiceAndFitTheAverages() {
        val flow = flow(listOf(0.0, 45.0, 90.0), takes = 2)
        // Round 1 reads 10 % high, round 2 10 % low: each pose's point is the exact exponential.
        val truth = { deg: Double -> 20.0 * exp(0.02 * deg) }
        assertEquals(CalibrationState.WaitingForPose(1, 45.0, 1), hold(flow, truth(0.0) * 1.1))
        assertEquals(CalibrationState.WaitingForPose(2, 90.0, 1), hold(flow, truth(45.0) * 1.1))
        assertEquals(CalibrationState.WaitingForPose(0, 0.0, 2), hold(flow, truth(90.0) * 1.1))
        assertEquals(3, flow.capturedTakes)
        // After round 1, a point is its one take.
        assertEquals(truth(45.0) * 1.1, flow.points[1].kiloohms, 1e-9)
        flow.beginPose()
        assertEquals(CalibrationState.Settling(0, 0.0, 1, null, 0, 2), flow.offer(r(truth(0.0) * 0.9)))
        repeat(2) { flow.offer(r(truth(0.0) * 0.9)) }
        hold(flow, truth(45.0) * 0.9)
        val end = hold(flow, truth(90.0) * 0.9)
        val fit = (end as CalibrationState.Calibrated).fit
        assertEquals(0.02, fit.calibration.alphaPerDegree, 1e-12)
        assertEquals(20.0, fit.calibration.betaKiloohms, 1e-10)
        assertEquals(listOf(0.0, 45.0, 90.0, 0.0, 45.0, 90.0), flow.takes.map { it.degrees })
        assertEquals(listOf(20.0, truth(45.0), truth(90.0)).map { Math.round(it * 1e9) }, flow.points.map { Math.round(it.kiloohms * 1e9) })
    }

    @Test
    fun constructor_takesOutOfRange_isRejected() {
        for (bad in listOf(0, 11)) {
            try {
                flow(takes = bad)
                fail("accepted $bad")
            } catch (_: IllegalArgumentException) {
            }
        }
    }

    @Test
    fun allPoses_withoutBending_endFailedAndRestartStartsOver() {
        val flow = flow(listOf(0.0, 90.0))
        hold(flow, 20.0)
        val end = hold(flow, 20.0)
        assertEquals(CalibrationState.Failed("fitted α = 0.0 per degree: the resistance does not rise with bending"), end)
        assertEquals(CalibrationState.Failed("fitted α = 0.0 per degree: the resistance does not rise with bending"), flow.beginPose())
        assertEquals(CalibrationState.WaitingForPose(0, 0.0), flow.restart())
        assertEquals(emptyList<CalibrationPoint>(), flow.points)
    }

    @Test
    fun beginPose_whileSettling_changesNothing() {
        val flow = flow()
        flow.beginPose()
        flow.offer(r(20.0))
        assertEquals(CalibrationState.Settling(0, 0.0, 1, null, 0), flow.beginPose())
    }

    @Test
    fun constructor_fewerThanTwoDistinctPosesOrBadCriterion_isRejected() {
        for (make in listOf(
            { FlexCalibrationFlow(GloveFinger.THUMB, listOf(30.0, 30.0)) },
            { FlexCalibrationFlow(GloveFinger.THUMB, listOf(0.0, Double.NaN)) },
            { SettleCriterion(windowSamples = 1) },
            { SettleCriterion(maxRelativeSpread = 0.0) },
        )) {
            try {
                make()
                fail("accepted")
            } catch (e: IllegalArgumentException) {
                assertTrue(e.message!!.isNotEmpty())
            }
        }
    }
}
