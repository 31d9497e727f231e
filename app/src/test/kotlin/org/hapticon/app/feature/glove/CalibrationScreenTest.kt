package org.hapticon.app.feature.glove

import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import org.hapticon.app.designsystem.HapticonTheme
import org.hapticon.app.sensors.TestCalibrationStore
import org.hapticon.app.sensors.TestClock
import org.hapticon.app.sensors.TestGloveSource
import org.hapticon.sensor.glove.FlexCalibration
import org.hapticon.sensor.glove.GloveFinger
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** The calibration flow driven through its UI with scripted flex-sensor readings. */
@RunWith(RobolectricTestRunner::class)
class CalibrationScreenTest {
    @get:Rule
    val rule = createComposeRule()

    private val glove = TestGloveSource()
    private val store = TestCalibrationStore()
    private val clock = TestClock()
    private var backs = 0
    private lateinit var viewModel: CalibrationViewModel

    @Before
    fun setUp() {
        viewModel = CalibrationViewModel(glove, store, clock, wallClockMillis = { 1_700_000_000_000L })
        rule.setContent { HapticonTheme { CalibrationRoute(viewModel, onBack = { backs++ }) } }
    }

    private fun startPose(degrees: Int) {
        rule.onNodeWithText("Start $degrees° pose").performScrollTo().performClick()
        rule.waitForIdle()
    }

    /** [count] readings of a sensor at [degrees] with [truth], 50 ms apart (each one reaches the UI). */
    private fun hold(finger: GloveFinger, degrees: Double, truth: FlexCalibration, count: Int) {
        val volts = glove.voltsAt(degrees, truth)
        repeat(count) {
            if (finger == GloveFinger.THUMB) glove.push(volts, Double.NaN) else glove.push(Double.NaN, volts)
            clock.advanceMillis(50)
        }
        rule.waitForIdle()
    }

    /** Each pose twice, round by round (the tele-handshake paper's two takes, averaged). */
    private fun calibrate(finger: GloveFinger, truth: FlexCalibration) {
        for (take in 1..2) {
            for ((i, pose) in listOf(0, 30, 50, 70, 90).withIndex()) {
                rule.onNodeWithText("Hold $pose° (take $take of 2)").assertExists()
                rule.onNodeWithText("Takes captured: ${(take - 1) * 5 + i} of 10").assertExists()
                startPose(pose)
                hold(finger, pose.toDouble(), truth, 25)
            }
        }
    }

    @Test
    fun thumbAndMiddle_walkEveryPoseToAFittedResultSavedForTheParticipant() {
        val thumb = FlexCalibration(0.017, 15.5)
        calibrate(GloveFinger.THUMB, thumb)

        rule.onNodeWithText("Calibrated").assertExists()
        rule.onNodeWithText("Takes captured: 10 of 10").assertExists()
        rule.onNodeWithText("α = 0.0170 per degree").assertExists()
        rule.onNodeWithText("β = 15.50 kΩ").assertExists()
        rule.onNodeWithText("R² = 1.0000").assertExists()
        rule.onNodeWithText("Saved for participant-1").assertExists()
        val savedThumb = store.load("participant-1", GloveFinger.THUMB)!!
        assertEquals(0.017, savedThumb.calibration.alphaPerDegree, 1e-9)
        assertEquals(15.5, savedThumb.calibration.betaKiloohms, 1e-6)
        assertEquals(1_700_000_000_000L, savedThumb.savedAtMillis)
        assertNull(store.load("participant-1", GloveFinger.MIDDLE))

        rule.onNodeWithText("Middle finger").performClick()
        rule.waitForIdle()
        calibrate(GloveFinger.MIDDLE, FlexCalibration.MIDDLE_DEFAULT)

        rule.onNodeWithText("α = 0.0190 per degree").assertExists()
        rule.onNodeWithText("β = 16.24 kΩ").assertExists()
        assertEquals(0.019, store.load("participant-1", GloveFinger.MIDDLE)!!.calibration.alphaPerDegree, 1e-9)
    }

    @Test
    fun settling_showsProgressAndWhetherTheFingerIsStillMoving() {
        startPose(0)
        hold(GloveFinger.THUMB, 0.0, FlexCalibration.THUMB_DEFAULT, 10)

        rule.onNodeWithText("Settling at 0° (take 1 of 2)…").assertExists()
        rule.onNodeWithText("10 of 25 steady readings").assertExists()

        // A finger still bending: 3 % apart within the window.
        val a = glove.divider.voltsFor(20.0)
        val b = glove.divider.voltsFor(20.6)
        repeat(15) { k ->
            glove.push(if (k % 2 == 0) a else b, Double.NaN)
            clock.advanceMillis(50)
        }
        rule.waitForIdle()
        rule.onNodeWithText("Still moving: spread", substring = true).assertExists()
        rule.onNodeWithText("Sensor now:", substring = true).assertExists()

        // An unplugged sensor (supply voltage) is a fault: the window starts over.
        glove.push(glove.divider.supplyVolts, Double.NaN)
        clock.advanceMillis(50)
        rule.waitForIdle()
        rule.onNodeWithText("1 sensor faults: the reading started over").assertExists()
        rule.onNodeWithText("Sensor fault: open circuit (sensor unplugged?)").assertExists()
    }

    @Test
    fun resistanceFallingWithBending_failsWithTheReason() {
        for ((i, pose) in (listOf(0, 30, 50, 70, 90) + listOf(0, 30, 50, 70, 90)).withIndex().map { (k, p) -> IndexedValue(k % 5, p) }) {
            startPose(pose)
            val volts = glove.divider.voltsFor(60.0 - 10.0 * i)
            repeat(25) {
                glove.push(volts, Double.NaN)
                clock.advanceMillis(50)
            }
            rule.waitForIdle()
        }

        rule.onNodeWithText("Calibration failed").assertExists()
        rule.onNodeWithText("the resistance does not rise with bending", substring = true).assertExists()
        assertNull(store.load("participant-1", GloveFinger.THUMB))

        rule.onNodeWithText("Try again").performScrollTo().performClick()
        rule.waitForIdle()
        rule.onNodeWithText("Hold 0° (take 1 of 2)").assertExists()
    }

    @Test
    fun backButton_isLabelledAndGoesBack() {
        rule.onNodeWithContentDescription("Back").performClick()
        assertEquals(1, backs)
    }

    @Test
    fun noGlove_explainsAndDisablesStart() {
        glove.connectedFlow.value = false
        rule.waitForIdle()
        rule.onNodeWithText("No glove is streaming", substring = true).assertExists()
    }
}
