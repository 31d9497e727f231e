package org.hapticon.app.feature.sensors

import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** The calibration route on the real main dispatcher: taps reach the view model and its state comes back to the screen. */
@RunWith(RobolectricTestRunner::class)
class ElectrotactileCalibrationRouteTest {
    @get:Rule
    val compose = createComposeRule()

    @Test
    fun route_clearAndPainFree_movesToTheNextElectrode() {
        val viewModel = ElectrotactileCalibrationViewModel(TestStimulatorLink(ready = false))
        compose.setContent { ElectrotactileCalibrationRoute(viewModel, onBack = {}) }
        compose.onNodeWithText("Electrode 1 of 9 (row 1, column 1)").assertExists()

        compose.onNodeWithText("Not yet: stronger").performScrollTo().performClick()
        compose.onNodeWithText("Not yet: stronger").performScrollTo().performClick()
        compose.onNodeWithText("Clear and pain-free").performScrollTo().performClick()
        compose.waitForIdle()

        compose.onNodeWithText("Electrode 2 of 9 (row 1, column 2)").assertExists()
        compose.onNodeWithContentDescription("Electrode 1: 0.837 mA").assertExists()
    }
}
