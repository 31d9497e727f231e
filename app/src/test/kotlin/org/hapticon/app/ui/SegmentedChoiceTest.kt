package org.hapticon.app.ui

import androidx.compose.foundation.layout.width
import androidx.compose.runtime.CompositionLocalProvider
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.setValue
import androidx.compose.ui.Modifier
import androidx.compose.ui.platform.LocalDensity
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.assert
import androidx.compose.ui.test.assertIsNotSelected
import androidx.compose.ui.test.assertIsSelected
import androidx.compose.ui.test.getBoundsInRoot
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.unit.Density
import androidx.compose.ui.unit.dp
import org.hapticon.app.designsystem.HapticonTheme
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config
import org.robolectric.annotation.GraphicsMode

/** The Sensors screen's protocol choice at the default and the largest font scale, on a 411 dp wide phone; and one whose selected value is not among its options. */
// Native graphics: the choice measures its labels, and only Robolectric's native text rendering measures real glyphs.
@RunWith(RobolectricTestRunner::class)
@GraphicsMode(GraphicsMode.Mode.NATIVE)
@Config(sdk = [35], qualifiers = "w411dp-h891dp-xxhdpi")
class SegmentedChoiceTest {
    @get:Rule
    val compose = createComposeRule()

    private val options = listOf("CSV", "LucidGloves", "Framed")
    private var selected by mutableStateOf("Framed")

    private fun show(fontScale: Float) = compose.setContent {
        val density = LocalDensity.current
        CompositionLocalProvider(LocalDensity provides Density(density.density, fontScale)) {
            HapticonTheme(dynamicColor = false) {
                SegmentedChoice(SingleChoice(options, selected) { it }, { selected = it }, Modifier.width(379.dp))
            }
        }
    }

    private fun bounds(label: String) = compose.onNodeWithText(label).getBoundsInRoot()

    @Test
    fun defaultFont_threeEqualSegmentsSideBySide() {
        show(1f)
        val csv = bounds("CSV")
        val gloves = bounds("LucidGloves")
        val framed = bounds("Framed")
        // One row: the same top, each a third of the width, in order.
        assertEquals(csv.top, gloves.top)
        assertEquals(csv.top, framed.top)
        assertEquals((csv.right - csv.left).value, (gloves.right - gloves.left).value, 1f)
        assertEquals(379f / 3, (gloves.right - gloves.left).value, 1.5f)
        // (Material overlaps neighbouring segments' 1 dp outlines.)
        assertTrue(csv.left < gloves.left && gloves.left < framed.left && gloves.left >= csv.right - 1.dp)
    }

    @Test
    fun largestFont_radioRowsOneUnderTheOther_eachFullWidthAndChoosable() {
        show(2f)
        val csv = bounds("CSV")
        val gloves = bounds("LucidGloves")
        val framed = bounds("Framed")
        // Stacked, never side by side: "LucidGloves" at twice the size does not fit a third of 379 dp.
        assertTrue("stacked: $csv $gloves $framed", csv.bottom <= gloves.top && gloves.bottom <= framed.top)
        for (b in listOf(csv, gloves, framed)) {
            assertEquals(379f, (b.right - b.left).value, 0.5f)
            assertTrue("48 dp high: $b", (b.bottom - b.top).value >= 48f)
        }
        compose.onNodeWithText("LucidGloves").assert(SemanticsMatcher.expectValue(SemanticsProperties.Role, Role.RadioButton))
        compose.onNodeWithText("LucidGloves").performClick()
        assertEquals("LucidGloves", selected)
        compose.onNodeWithText("LucidGloves").assertIsSelected()
    }

    /** A selected value that is not among the options (allowed by [SingleChoice]) marks no segment, and a tap picks one. */
    @Test
    fun selectedOutsideOptions_noSegmentSelected_aTapSelectsOne() {
        selected = "USB"
        show(1f)
        for (label in options) compose.onNodeWithText(label).assertIsNotSelected()
        compose.onNodeWithText("CSV").performClick()
        assertEquals("CSV", selected)
        compose.onNodeWithText("CSV").assertIsSelected()
        compose.onNodeWithText("Framed").assertIsNotSelected()
    }
}
