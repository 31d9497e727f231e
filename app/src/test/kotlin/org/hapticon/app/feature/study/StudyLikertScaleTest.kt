package org.hapticon.app.feature.study

import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.remember
import androidx.compose.runtime.setValue
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.assertIsNotSelected
import androidx.compose.ui.test.assertIsSelected
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import org.hapticon.app.designsystem.HapticonTheme
import org.hapticon.study.LikertScale
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

@RunWith(RobolectricTestRunner::class)
class StudyLikertScaleTest {
    @get:Rule val rule = createComposeRule()

    private val chosen = ArrayList<Int>()

    private fun show(scale: LikertScale) {
        rule.setContent {
            HapticonTheme {
                var selected by remember { mutableStateOf<Int?>(null) }
                LikertScaleControl(scale, selected, onSelect = { selected = it; chosen += it })
            }
        }
    }

    @Test
    fun fivePoints_eachIsARadioButtonNamedWithItsLabel_andTheEndsAreWritten() {
        show(LikertScale.AGREEMENT_5)

        val radios = rule.onAllNodes(SemanticsMatcher.expectValue(SemanticsProperties.Role, Role.RadioButton)).fetchSemanticsNodes()
        assertEquals(5, radios.size)
        rule.onNodeWithText("strongly disagree").assertExists()
        rule.onNodeWithText("strongly agree").assertExists()
        rule.onNodeWithContentDescription("3 of 5: neither agree nor disagree").assertIsNotSelected()

        rule.onNodeWithContentDescription("4 of 5: agree").performClick()
        rule.onNodeWithContentDescription("4 of 5: agree").assertIsSelected()
        rule.onNodeWithContentDescription("1 of 5: strongly disagree").performClick()
        rule.onNodeWithContentDescription("1 of 5: strongly disagree").assertIsSelected()
        rule.onNodeWithContentDescription("4 of 5: agree").assertIsNotSelected()
        assertEquals(listOf(4, 1), chosen)
    }

    @Test
    fun sevenPointsWithTwoAnchors_labelsOnlyTheEnds() {
        show(LikertScale(7, listOf("never", "always")))

        rule.onNodeWithContentDescription("1 of 7: never").assertExists()
        rule.onNodeWithContentDescription("4 of 7").performClick()
        rule.onNodeWithContentDescription("4 of 7").assertIsSelected()
        rule.onNodeWithContentDescription("7 of 7: always").assertIsNotSelected()
        assertEquals(listOf(4), chosen)
    }
}
