package org.hapticon.app.screenshots

import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import org.hapticon.app.feature.glove.CalibrationRoute
import org.hapticon.app.feature.glove.CalibrationViewModel
import org.hapticon.app.sensors.TestCalibrationStore
import org.hapticon.app.sensors.TestClock
import org.hapticon.app.sensors.TestGloveSource
import org.hapticon.sensor.glove.FlexCalibration
import org.junit.Test

/** The glove calibration (Sensors › Calibrate glove), at its start and with the thumb fitted. */
class GloveScreenshotTest : ScreenshotTest() {
    private val glove = TestGloveSource()
    private val clock = TestClock()
    private val viewModel = CalibrationViewModel(glove, TestCalibrationStore(), clock, wallClockMillis = { 1_700_000_000_000L })

    @Test
    fun calibration_start() = screen("glove-calibration", Variant.MAIN) {
        CalibrationRoute(viewModel, onBack = {})
    }

    /**
     * Every pose held twice (the paper's calibration takes each pose twice and averages) for 25 readings of a
     * thumb with α 0.017/°, β 15.5 kΩ: the fit and its R².
     */
    @Test
    fun calibration_thumbFitted() = screen("glove-calibration-fitted", prepare = {
        val truth = FlexCalibration(0.017, 15.5)
        for (pose in listOf(0, 30, 50, 70, 90) + listOf(0, 30, 50, 70, 90)) {
            compose.onNodeWithText("Start $pose° pose").performScrollTo().performClick()
            compose.waitForIdle()
            val volts = glove.voltsAt(pose.toDouble(), truth)
            repeat(25) {
                glove.push(volts, Double.NaN)
                clock.advanceMillis(50)
            }
            compose.waitForIdle()
        }
        compose.onNodeWithText("Calibrated").performScrollTo()
    }) {
        CalibrationRoute(viewModel, onBack = {})
    }
}
