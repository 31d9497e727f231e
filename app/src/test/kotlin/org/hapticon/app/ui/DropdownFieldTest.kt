package org.hapticon.app.ui

import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableIntStateOf
import androidx.compose.runtime.setValue
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.assert
import androidx.compose.ui.test.assertCountEquals
import androidx.compose.ui.test.hasContentDescription
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onAllNodesWithText
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import org.hapticon.app.designsystem.HapticonTheme
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config

/**
 * A [DropdownField] whose selected value is not among its options (the compliance setup's participant number past
 * the 40 it lists, a glove channel the board no longer reports): [SingleChoice] allows it, so the field must show
 * the value and still offer exactly its options.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class DropdownFieldTest {
    @get:Rule
    val compose = createComposeRule()

    private var selected by mutableIntStateOf(7)

    private fun field() = compose.onNode(hasContentDescription("Participant number"))

    @Test
    fun selectedOutsideOptions_isShown_andTheMenuOffersOnlyTheOptions() {
        compose.setContent {
            HapticonTheme(dynamicColor = false) {
                DropdownField("Participant number", SingleChoice(listOf(1, 2, 3), selected) { "#$it" }, { selected = it })
            }
        }
        field().assert(SemanticsMatcher.expectValue(SemanticsProperties.StateDescription, "#7"))
        compose.onAllNodesWithText("#", substring = true).assertCountEquals(1)

        field().performClick()
        // The button and the three options; "#7" is not added to the menu.
        compose.onAllNodesWithText("#", substring = true).assertCountEquals(4)
        compose.onAllNodesWithText("#7").assertCountEquals(1)

        compose.onNodeWithText("#2").performClick()
        assertEquals(2, selected)
        field().assert(SemanticsMatcher.expectValue(SemanticsProperties.StateDescription, "#2"))
        compose.onAllNodesWithText("#", substring = true).assertCountEquals(1)
    }
}
