package org.hapticon.app.feature.chat

import androidx.compose.runtime.CompositionLocalProvider
import androidx.compose.ui.platform.LocalDensity
import androidx.compose.ui.semantics.SemanticsActions
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.test.hasContentDescription
import androidx.compose.ui.test.hasSetTextAction
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithTag
import androidx.compose.ui.test.performClick
import androidx.compose.ui.text.TextLayoutResult
import androidx.compose.ui.text.style.TextOverflow
import androidx.compose.ui.unit.Density
import org.hapticon.app.data.ChatPreferences
import org.hapticon.core.render.RendererKind
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config
import org.robolectric.annotation.GraphicsMode

/**
 * The broker address in Settings, laid out with real fonts (native graphics, a Pixel 7's 411 × 891 dp): one line at
 * every font scale, cut in the middle when it does not fit (so "ssl://" and ":8883" stay in sight and the host is
 * never split from its port across lines), the whole address in its text for TalkBack and in the "Change" field.
 */
@RunWith(RobolectricTestRunner::class)
@GraphicsMode(GraphicsMode.Mode.NATIVE)
@Config(sdk = [35], qualifiers = "w411dp-h891dp-xxhdpi")
class SettingsBrokerUrlTest {
    @get:Rule
    val compose = createComposeRule()

    private val url = "ssl://broker.example.org:8883"

    private fun show(fontScale: Float) = compose.setContent {
        val density = LocalDensity.current
        CompositionLocalProvider(LocalDensity provides Density(density.density, fontScale)) {
            SettingsScreen(
                SettingsUiState(ChatPreferences(userName = "alice", brokerUrl = url), listOf(RendererKind.AMPLITUDE_WAVEFORM), "connected"),
                SettingsActions(),
            )
        }
    }

    private fun layout(): TextLayoutResult {
        val layouts = mutableListOf<TextLayoutResult>()
        compose.onNodeWithTag(BROKER_URL_TAG).fetchSemanticsNode().config[SemanticsActions.GetTextLayoutResult].action!!.invoke(layouts)
        return layouts.single()
    }

    private fun shownText(): String =
        compose.onNodeWithTag(BROKER_URL_TAG).fetchSemanticsNode().config[SemanticsProperties.Text].joinToString("") { it.text }

    @Test
    fun largestFont_oneLineCutInTheMiddle_fullAddressInItsText() {
        show(2f)
        val layout = layout()
        assertEquals(1, layout.lineCount)
        assertTrue("not cut at 2.0", layout.isLineEllipsized(0))
        assertEquals(TextOverflow.MiddleEllipsis, layout.layoutInput.overflow)
        assertEquals(1, layout.layoutInput.maxLines)
        assertEquals(url, shownText())
    }

    @Test
    fun defaultFont_fitsWhole() {
        show(1f)
        val layout = layout()
        assertEquals(1, layout.lineCount)
        assertFalse(layout.isLineEllipsized(0))
        assertEquals(url, shownText())
    }

    @Test
    fun change_opensTheFieldWithTheWholeAddress() {
        show(2f)
        // The second "Change", after the user name's.
        compose.onAllNodes(hasText("Change"))[1].performClick()
        val field = compose.onNode(hasContentDescription("Broker") and hasSetTextAction())
        assertEquals(url, field.fetchSemanticsNode().config[SemanticsProperties.EditableText].text)
    }
}
