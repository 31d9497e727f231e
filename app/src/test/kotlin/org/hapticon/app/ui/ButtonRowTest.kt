package org.hapticon.app.ui

import androidx.compose.foundation.layout.width
import androidx.compose.material3.Button
import androidx.compose.material3.OutlinedButton
import androidx.compose.material3.Text
import androidx.compose.runtime.CompositionLocalProvider
import androidx.compose.ui.Modifier
import androidx.compose.ui.platform.LocalDensity
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

/**
 * The compliance trial's two buttons ("Next", "Send condition again") in a [ButtonRow] 379 dp wide (a 411 dp phone
 * less its margins), at the default and the largest font scale; and a label longer than the row in a
 * [WrappingButtonShape] button. Native graphics: the decision measures real glyphs.
 */
@RunWith(RobolectricTestRunner::class)
@GraphicsMode(GraphicsMode.Mode.NATIVE)
@Config(sdk = [35], qualifiers = "w411dp-h891dp-xxhdpi")
class ButtonRowTest {
    @get:Rule
    val compose = createComposeRule()

    private var clicked = ""

    private fun show(fontScale: Float) = compose.setContent {
        val density = LocalDensity.current
        CompositionLocalProvider(LocalDensity provides Density(density.density, fontScale)) {
            HapticonTheme(dynamicColor = false) {
                ButtonRow(Modifier.width(379.dp)) {
                    Button(onClick = { clicked = "next" }) { Text("Next") }
                    OutlinedButton(onClick = { clicked = "again" }) { Text("Send condition again") }
                }
            }
        }
    }

    private fun bounds(label: String) = compose.onNodeWithText(label, useUnmergedTree = true).getBoundsInRoot()

    /** The button around [label]: its merged node (the label's own node is the text inside it). */
    private fun button(label: String) = compose.onNodeWithText(label).getBoundsInRoot()

    @Test
    fun defaultFont_sideBySide_eachLabelOnOneLine() {
        show(1f)
        val next = button("Next")
        val again = button("Send condition again")
        assertEquals(next.top, again.top)
        // 12 dp apart, in order, each as wide as its label needs (well under the row's width).
        assertEquals(12f, (again.left - next.right).value, 0.5f)
        assertTrue("natural widths: $next $again", (again.right - next.left).value < 379f)
        // One line: the label is no taller than Material's 40 dp button.
        assertTrue("one line: ${bounds("Send condition again")}", (bounds("Send condition again").bottom - bounds("Send condition again").top).value < 40f)
    }

    @Test
    fun largestFont_stacked_fullWidth_oneLineEach_andStillPressable() {
        show(2f)
        val next = button("Next")
        val again = button("Send condition again")
        // Stacked 12 dp apart, both the row's full width.
        assertEquals(12f, (again.top - next.bottom).value, 0.5f)
        for (b in listOf(next, again)) assertEquals(379f, (b.right - b.left).value, 0.5f)
        // The long label keeps one line (twice the 20 sp line height, not two lines of it).
        val label = bounds("Send condition again")
        assertTrue("one line at 2.0: $label", (label.bottom - label.top).value < 2 * 40f)
        compose.onNodeWithText("Send condition again").performClick()
        assertEquals("again", clicked)
    }

    @Test
    fun wrappingButtonShape_isThePillForOneLine_andCaps32dpForMore() {
        val density = Density(3f)
        val shape = WrappingButtonShape
        fun radius(heightDp: Float): Float {
            val size = androidx.compose.ui.geometry.Size(300f * 3, heightDp * 3)
            val outline = shape.createOutline(size, androidx.compose.ui.unit.LayoutDirection.Ltr, density)
            return (outline as androidx.compose.ui.graphics.Outline.Rounded).roundRect.topLeftCornerRadius.x / 3
        }
        // A 40 dp (font 1.0) and a 60 dp (font 2.0) one-line button: exactly half the height, a pill.
        assertEquals(20f, radius(40f), 0.01f)
        assertEquals(30f, radius(60f), 0.01f)
        // A 100 dp two-line button: 32 dp corners, not a 50 dp oval.
        assertEquals(32f, radius(100f), 0.01f)
    }
}
