package org.hapticon.app.feature.chat

import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.width
import androidx.compose.runtime.CompositionLocalProvider
import androidx.compose.ui.Modifier
import androidx.compose.ui.platform.LocalDensity
import androidx.compose.ui.semantics.Role
import androidx.compose.ui.semantics.SemanticsActions
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.semantics.getOrNull
import androidx.compose.ui.test.SemanticsNodeInteraction
import androidx.compose.ui.test.assertIsDisplayed
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithTag
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performSemanticsAction
import androidx.compose.ui.text.TextLayoutResult
import androidx.compose.ui.unit.Density
import androidx.compose.ui.unit.Dp
import androidx.compose.ui.unit.dp
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.RendererKind
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config
import org.robolectric.annotation.GraphicsMode

/**
 * The composer's "how it will feel there" lines at the largest font scale (2.0), laid out with real fonts (native
 * graphics, a Pixel 7's 411 × 891 dp): with a pitch and an envelope line they collapse to a short summary, which a tap,
 * or TalkBack's double-tap or expand action, opens to show every line, and the message field and Send stay on screen.
 * The short summary wraps, never cut, also on a 360 dp phone.
 */
@RunWith(RobolectricTestRunner::class)
@GraphicsMode(GraphicsMode.Mode.NATIVE)
@Config(sdk = [35], qualifiers = "w411dp-h891dp-xxhdpi")
class ComposerFeelLinesTest {
    @get:Rule
    val compose = createComposeRule()

    private val summary = "How hug will feel there: envelope effect"
    private val collapsedSummary = "Envelope effect on bob's phone"
    private val pitchLine = "bob's phone (120–240\u00A0Hz): 147\u00A0Hz → plays 147\u00A0Hz"
    private val envelopeLine = "bob's envelope: 4 control points (7 merged into 4 by its limits: 4 points, 50\u00A0ms–1\u00A0s each, 4\u00A0s in all)"

    private fun show(feel: PeerFeel, fontScale: Float = 2f, width: Dp = 411.dp) = compose.setContent {
        val density = LocalDensity.current
        CompositionLocalProvider(LocalDensity provides Density(density.density, fontScale)) {
            Box(Modifier.width(width)) {
                ConversationScreen(
                    ConversationUiState.Success(
                        peer = "bob", messages = emptyList(), icons = HapticIcon.PRESETS, selectedIcon = HapticIcon.HUG,
                        selectedSticker = null, peerFeel = feel, error = null,
                    ),
                    ConversationActions(),
                )
            }
        }
    }

    private val withDetails = PeerFeel(
        RendererKind.ENVELOPE, null, pitch = "bob's phone (120–240 Hz): 147 Hz → plays 147 Hz",
        envelope = "bob's envelope: 4 control points (7 merged into 4 by its limits: 4 points, 50 ms–1 s each, 4 s in all)",
    )

    private fun control() = compose.onNodeWithTag(PEER_FEEL_TAG)

    private fun SemanticsNodeInteraction.state(): String? = fetchSemanticsNode().config.getOrNull(SemanticsProperties.StateDescription)

    /** How the summary line was laid out (its own Text node, unmerged). */
    private fun summaryLayout(text: String = summary): TextLayoutResult {
        val layouts = mutableListOf<TextLayoutResult>()
        compose.onNode(hasText(text), useUnmergedTree = true).fetchSemanticsNode()
            .config[SemanticsActions.GetTextLayoutResult].action!!.invoke(layouts)
        return layouts.single()
    }

    private fun assertFieldAndSendOnScreen() {
        compose.onNodeWithContentDescription("Message").assertIsDisplayed()
        compose.onNodeWithContentDescription("Send").assertIsDisplayed()
    }

    @Test
    fun collapsedByDefault_shortSummary_aButtonTalkBackCallsCollapsed() {
        show(withDetails)
        val node = control().fetchSemanticsNode()
        assertEquals(Role.Button, node.config.getOrNull(SemanticsProperties.Role))
        assertEquals("collapsed", control().state())
        assertEquals("Show details", node.config[SemanticsActions.OnClick].label)
        // At least 48 dp high (Material's minimum target) and the screen's width.
        val density = compose.density.density
        assertTrue("${node.size}", node.size.height >= 48 * density && node.size.width >= 380 * density)
        // The short summary that starts with the renderer, whole (it wraps at 2.0); the full wording waits behind the tap.
        assertWhole(summaryLayout(collapsedSummary))
        compose.onNodeWithText(summary).assertDoesNotExist()
        compose.onNodeWithText(pitchLine).assertDoesNotExist()
        compose.onNodeWithText(envelopeLine).assertDoesNotExist()
        assertFieldAndSendOnScreen()
    }

    @Test
    fun tapped_showsEveryLineInFull_tappedAgainCollapses() {
        show(withDetails)
        control().performClick()
        assertEquals("expanded", control().state())
        assertEquals("Hide details", control().fetchSemanticsNode().config[SemanticsActions.OnClick].label)
        // The summary wraps in full now, and the pitch and envelope lines follow, each number with its unit.
        val layout = summaryLayout()
        assertTrue("${layout.lineCount} lines", layout.lineCount >= 2)
        assertTrue(!layout.isLineEllipsized(layout.lineCount - 1))
        compose.onNodeWithText(pitchLine, useUnmergedTree = true).assertIsDisplayed()
        compose.onNodeWithText(envelopeLine, useUnmergedTree = true).assertIsDisplayed()
        assertFieldAndSendOnScreen()

        control().performClick()
        assertEquals("collapsed", control().state())
        compose.onNodeWithText(pitchLine).assertDoesNotExist()
        assertWhole(summaryLayout(collapsedSummary))
    }

    private fun assertWhole(layout: TextLayoutResult) =
        assertTrue("cut: ${layout.lineCount} lines", (0 until layout.lineCount).none { layout.isLineEllipsized(it) })

    @Test
    fun talkBackExpandAndCollapseActions_openAndCloseTheLines() {
        show(withDetails)
        // Only the action that applies is offered (TalkBack lists it in its actions menu).
        assertNull(control().fetchSemanticsNode().config.getOrNull(SemanticsActions.Collapse))
        control().performSemanticsAction(SemanticsActions.Expand)
        assertEquals("expanded", control().state())
        compose.onNodeWithText(envelopeLine, useUnmergedTree = true).assertIsDisplayed()
        assertNull(control().fetchSemanticsNode().config.getOrNull(SemanticsActions.Expand))
        control().performSemanticsAction(SemanticsActions.Collapse)
        assertEquals("collapsed", control().state())
        compose.onNodeWithText(envelopeLine).assertDoesNotExist()
    }

    /** 360 dp and font 2.0: the collapsed summary wraps whole; cut to one line it read "Amplitude waveform on bo…". */
    @Test
    fun smallPhoneLargestFont_collapsedSummaryWrapsWhole() {
        show(withDetails.copy(renderer = RendererKind.AMPLITUDE_WAVEFORM, fidelityPercent = 93), width = 360.dp)
        assertEquals("collapsed", control().state())
        val layout = summaryLayout("Amplitude waveform on bob's phone, 93% fidelity")
        assertTrue("${layout.lineCount} lines", layout.lineCount >= 2)
        assertWhole(layout)
        assertFieldAndSendOnScreen()
    }

    @Test
    fun noPitchOrEnvelope_theLineStandsAloneWithNothingToExpand() {
        show(PeerFeel(RendererKind.ON_OFF, 61), fontScale = 1f)
        control().assertDoesNotExist()
        compose.onNodeWithText("How hug will feel there: on/off pattern, 61% fidelity").assertIsDisplayed()
    }
}
