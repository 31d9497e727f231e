package org.hapticon.app.feature.icons

import android.os.Vibrator
import org.hapticon.app.playback.lastUsage
import org.hapticon.core.platform.VibrationUsage
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.assert
import androidx.compose.ui.test.hasClickAction
import androidx.compose.ui.test.hasContentDescription
import androidx.compose.ui.test.hasScrollToNodeAction
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.junit4.createAndroidComposeRule
import androidx.compose.ui.test.onAllNodesWithText
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollToNode
import org.hapticon.app.MainActivity
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.lastVibration
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

@RunWith(RobolectricTestRunner::class)
class IconsScreenTest {
    @get:Rule
    val rule = createAndroidComposeRule<MainActivity>()

    private val vibrator get() = rule.activity.getSystemService(Vibrator::class.java)

    private fun scrollTo(matcher: SemanticsMatcher) {
        // The app opens on Chats.
        rule.onNode(hasText("Icons") and hasClickAction()).performClick()
        // The list comes from Room (presets plus custom icons): wait until it is on screen.
        rule.waitUntil(5_000) { rule.onAllNodes(hasScrollToNodeAction()).fetchSemanticsNodes().isNotEmpty() }
        rule.onNode(hasScrollToNodeAction()).performScrollToNode(matcher)
    }

    @Test
    fun iconList_showsEveryPresetWithItsParameters() {
        for (name in listOf("stroke", "hit", "knock", "hug")) {
            scrollTo(hasContentDescription("Play $name"))
            rule.onNodeWithContentDescription("Play $name").assertExists()
        }
        val knock = "A 0.005 s · S 0.01 s · L 0.5 · R 0.005 s · note 57 (220.0 Hz) · 3× every 0.27 s".replace(' ', '\u00A0').replace("\u00A0·\u00A0", " · ")
        scrollTo(hasText(knock))
        rule.onNodeWithText(knock).assertExists()
        val hug = "A 1.5 s · S 1 s · L 0.5 · R 0.5 s · note 50 (146.8 Hz)".replace(' ', '\u00A0').replace("\u00A0·\u00A0", " · ")
        scrollTo(hasText(hug))
        rule.onNodeWithText(hug).assertExists()
    }

    @Test
    fun pressingKnock_handsKnockWaveformToVibratorAndShowsPlaying() {
        shadowOf(vibrator).setHasAmplitudeControl(true)
        scrollTo(hasContentDescription("Play knock"))

        rule.onNodeWithContentDescription("Play knock").performClick()
        // The player renders off the main thread, then vibrates.
        rule.waitUntil(5_000) { rule.onAllNodesWithText("Playing 560 ms", substring = true).fetchSemanticsNodes().isNotEmpty() }

        assertEquals(
            RecordedVibration(timings = listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), amplitudes = listOf(175, 111, 0, 175, 111, 0, 175, 111)),
            lastVibration(vibrator),
        )
        // A press in the open app: a touch.
        assertEquals(VibrationUsage.TOUCH, lastUsage(vibrator))
        rule.onNodeWithContentDescription("Play knock")
            .assert(SemanticsMatcher.expectValue(SemanticsProperties.StateDescription, "playing"))
        rule.onNodeWithText("Playing 560 ms as amplitude waveform", substring = true).assertExists()
    }
}
