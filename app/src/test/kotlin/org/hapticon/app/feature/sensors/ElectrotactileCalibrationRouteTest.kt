package org.hapticon.app.feature.sensors

import org.hapticon.app.data.ElectrodeLevelsStore
import androidx.compose.ui.test.assertIsEnabled
import androidx.compose.ui.test.assertIsNotEnabled
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onAllNodesWithText
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import java.time.Instant
import org.junit.Rule
import org.junit.rules.TemporaryFolder
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** The calibration route on the real main dispatcher: taps reach the view model and its state comes back to the screen. */
@RunWith(RobolectricTestRunner::class)
class ElectrotactileCalibrationRouteTest {
    @get:Rule
    val compose = createComposeRule()

    @get:Rule
    val folder = TemporaryFolder()

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
        compose.onNodeWithText("None yet: the compliance study needs a finished calibration, or one imported from a file.").assertExists()
        compose.onNodeWithText("Export file").assertIsNotEnabled()
    }

    @Test
    fun route_showsTheStoredCalibration_readOffTheMainThread() {
        val store = ElectrodeLevelsStore(folder.newFile("calibration.json").also { it.delete() }) { Instant.parse("2026-11-27T00:12:03Z") }
        store.save(listOf(61, 62, 63, 64, 65, 66, 67, 68, 90))
        val viewModel = ElectrotactileCalibrationViewModel(TestStimulatorLink(ready = false), store)
        compose.setContent { ElectrotactileCalibrationRoute(viewModel, onBack = {}) }
        val line = "The compliance study uses the calibration of 2026-11-27 00:12 UTC (0.824–1.215 mA)."
        compose.waitUntil(5_000) { compose.onAllNodesWithText(line).fetchSemanticsNodes().isNotEmpty() }
        compose.onNodeWithText("Export file").performScrollTo().assertIsEnabled()
        compose.onNodeWithText("Import file").performScrollTo().assertIsEnabled()
    }
}
