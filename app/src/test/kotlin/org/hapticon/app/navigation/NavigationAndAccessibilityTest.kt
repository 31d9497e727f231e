package org.hapticon.app.navigation

import android.content.pm.PackageManager
import androidx.compose.ui.semantics.SemanticsActions
import androidx.compose.ui.semantics.SemanticsNode
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.semantics.getOrNull
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.hasClickAction
import androidx.compose.ui.test.hasScrollToNodeAction
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.isSelected
import androidx.compose.ui.test.junit4.createAndroidComposeRule
import androidx.compose.ui.test.onAllNodesWithContentDescription
import androidx.compose.ui.test.onAllNodesWithText
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollToNode
import androidx.compose.ui.test.performTextInput
import org.hapticon.app.MainActivity
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

/** The bottom bar, the Sensors sub-screens and Back, the Study tab's screens, and that every control has a name. */
@RunWith(RobolectricTestRunner::class)
class NavigationAndAccessibilityTest {
    @get:Rule
    val rule = createAndroidComposeRule<MainActivity>()

    private fun openSensors() {
        shadowOf(rule.activity.packageManager).setSystemFeature(PackageManager.FEATURE_USB_HOST, true)
        rule.onNode(hasText("Sensors") and hasClickAction()).performClick()
        rule.waitForIdle()
    }

    private fun scrollTo(matcher: SemanticsMatcher) {
        rule.onNode(hasScrollToNodeAction()).performScrollToNode(matcher)
    }

    /** Every clickable, toggleable or adjustable node reads as something: text, a content description or both. */
    private fun assertEveryControlIsNamed(screen: String) {
        val controls = rule.onAllNodes(
            hasClickAction() or SemanticsMatcher.keyIsDefined(SemanticsActions.SetProgress) or
                SemanticsMatcher.keyIsDefined(SemanticsProperties.ToggleableState),
        ).fetchSemanticsNodes()
        assertTrue("$screen has no controls", controls.isNotEmpty())
        val unnamed = controls.filter { !it.isNamed() }
        assertTrue("$screen: unnamed controls ${unnamed.map { it.config }}", unnamed.isEmpty())
    }

    private fun SemanticsNode.isNamed(): Boolean {
        val text = config.getOrNull(SemanticsProperties.Text)?.joinToString("").orEmpty()
        val description = config.getOrNull(SemanticsProperties.ContentDescription)?.joinToString("").orEmpty()
        return text.isNotBlank() || description.isNotBlank()
    }

    @Test
    fun studyTab_pinThenResearcherThenParticipantScreensWithoutTheBar() {
        rule.onNode(hasText("Study") and hasClickAction()).performClick()
        // The researcher screen shows a spinner until Room (on its own thread, which waitForIdle does not wait
        // for) has said whether a session is running; then the PIN gate.
        rule.waitUntil(5_000) { rule.onAllNodesWithText("Set a researcher PIN").fetchSemanticsNodes().isNotEmpty() }
        rule.onNodeWithText("Set a researcher PIN").assertExists()
        assertEveryControlIsNamed("Study PIN")
        rule.onNodeWithContentDescription("PIN").performTextInput("2580")
        rule.onNodeWithContentDescription("Repeat PIN").performTextInput("2580")
        rule.onNodeWithText("Set PIN").performClick()

        rule.waitUntil(5_000) { rule.onAllNodesWithText("Start session for P000-A").fetchSemanticsNodes().isNotEmpty() }
        assertEveryControlIsNamed("Study researcher")
        rule.onNodeWithText("Start session for P000-A").performClick()

        rule.waitUntil(5_000) { rule.onAllNodesWithText("Task 1: Haptic icons").fetchSemanticsNodes().isNotEmpty() }
        rule.onNode(hasText("Icons") and hasClickAction()).assertDoesNotExist()
        rule.onNodeWithText("Start").performClick()
        rule.waitUntil(5_000) { rule.onAllNodesWithContentDescription("Play haptic icon 1").fetchSemanticsNodes().isNotEmpty() }
        rule.onNodeWithText("Haptic icon 1 feels like stroking").assertExists()
        assertEveryControlIsNamed("Study trial")
    }

    @Test
    fun bottomBar_opensOnChats_switchesBetweenIconsAndSensors() {
        // A messenger opens on its chats (here the first-launch form: no account yet).
        rule.onNode(hasText("Chats") and isSelected()).assertExists()
        // The first-launch form once the settings and Room have answered (Room on its own thread).
        rule.waitUntil(10_000) { rule.onAllNodes(hasText("Welcome to Hapticon")).fetchSemanticsNodes().isNotEmpty() }
        assertEveryControlIsNamed("Chats")

        rule.onNode(hasText("Icons") and hasClickAction()).performClick()
        rule.waitForIdle()
        rule.onNode(hasText("Icons") and isSelected()).assertExists()
        assertEveryControlIsNamed("Icons")

        openSensors()

        rule.onNode(hasText("Sensors") and isSelected()).assertExists()
        rule.onNodeWithText("USB boards").assertExists()
        assertEveryControlIsNamed("Sensors")

        rule.onNode(hasText("Icons") and hasClickAction()).performClick()
        rule.waitForIdle()
        rule.onNodeWithText("Haptic icons").assertExists()
    }

    @Test
    fun calibration_opensFromSensorsAndBackReturns() {
        openSensors()
        scrollTo(hasText("Calibrate glove"))
        rule.onNodeWithText("Calibrate glove").performClick()
        rule.waitForIdle()

        rule.onNodeWithText("Glove calibration").assertExists()
        rule.onNodeWithText("Hold 0° (take 1 of 2)").assertExists()
        rule.onNodeWithText("No glove is streaming", substring = true).assertExists()
        assertEveryControlIsNamed("Calibration")

        rule.onNodeWithContentDescription("Back").performClick()
        rule.waitForIdle()
        rule.onNodeWithText("USB boards").assertExists()
    }

    @Test
    fun handshake_opensFromSensorsAndSystemBackReturns() {
        openSensors()
        scrollTo(hasText("Handshake"))
        rule.onNode(hasText("Handshake") and hasClickAction()).performClick()
        rule.waitForIdle()
        // The partner list comes from Room (the chat's conversations): wait for the screen to be ready.
        rule.waitUntil(5_000) { rule.onAllNodes(hasText("No handshake")).fetchSemanticsNodes().isNotEmpty() }

        rule.onNodeWithText("No handshake").assertExists()
        rule.onNodeWithText("Simulated partner").assertExists()
        rule.onNodeWithText("Palm").assertExists()
        assertEveryControlIsNamed("Handshake")

        rule.runOnUiThread { rule.activity.onBackPressedDispatcher.onBackPressed() }
        rule.waitForIdle()
        rule.onNodeWithText("USB boards").assertExists()
    }

    @Test
    fun gestures_everyTabOpensAndEveryControlIsNamed() {
        rule.onNode(hasText("Gestures") and hasClickAction()).performClick()
        rule.waitForIdle()
        rule.onNodeWithText("Touch here").assertExists()
        assertEveryControlIsNamed("Gestures: Record")
        for (tab in listOf("Teach", "Recognise")) {
            rule.onNode(hasText(tab) and hasClickAction()).performClick()
            rule.waitForIdle()
            assertEveryControlIsNamed("Gestures: $tab")
        }
        rule.onNodeWithText("No model: teach or import one in the Teach tab").assertExists()
    }
}
