package org.hapticon.app.feature.gesture

import androidx.compose.foundation.layout.Column
import androidx.compose.ui.test.assertCountEquals
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onAllNodesWithText
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import org.hapticon.app.gesture.SavedRecording
import org.hapticon.core.HapticIcon
import org.hapticon.gesture.extraction.IconFitter
import org.hapticon.gesture.extraction.NoisyIconRenders
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import java.util.Random

/** The recorder's batch fit against the strongest saved gesture, as shown. */
@RunWith(RobolectricTestRunner::class)
class StrongestBatchSectionTest {
    @get:Rule
    val compose = createComposeRule()

    private val saved = listOf(SavedRecording("a", "loud", null, 4000, 0.5), SavedRecording("b", "soft", null, 4000, 0.5))

    @Test
    fun section_withABatch_listsEachIconsLevelAndTheReference_andSavesAll() {
        val take = NoisyIconRenders.render(HapticIcon.KNOCK, Double.POSITIVE_INFINITY, Random(1), sampleRate = 8000).toRecording()
        val fits = IconFitter.fitBatch(listOf(take, take))
        val state = RecorderUiState.Ready(savedRecordings = saved, batch = listOf(BatchIcon("loud", fits[0]), BatchIcon("soft", fits[1])))
        var fitted = 0
        var savedAll = 0
        compose.setContent { Column { StrongestBatchSection(state, onFit = { fitted++ }, onSave = { savedAll++ }) } }

        val level = String.format(java.util.Locale.ROOT, "level %.2f", fits[0].icon.level)
        compose.onNodeWithText("loud").assertExists()
        compose.onNodeWithText("soft").assertExists()
        compose.onNodeWithText("Reference: the strongest gesture of the batch of 2", substring = true).assertExists()
        // The same take twice: both are the strongest, so both rows show the same level.
        compose.onAllNodesWithText(level, substring = true).assertCountEquals(2)
        compose.onNodeWithText("Fit all (strongest = 1)").performClick()
        compose.onNodeWithText("Save all 2 icons").performClick()
        assertEquals(1 to 1, fitted to savedAll)
    }

    @Test
    fun section_withFewerThanTwoSavedRecordings_isNotShown() {
        compose.setContent { Column { StrongestBatchSection(RecorderUiState.Ready(savedRecordings = saved.take(1)), onFit = {}, onSave = {}) } }
        compose.onNodeWithText("Fit all (strongest = 1)").assertDoesNotExist()
    }
}
