package org.hapticon.app.feature.chat

import android.view.View
import androidx.compose.ui.geometry.Rect
import androidx.compose.ui.input.key.Key
import androidx.compose.ui.platform.LocalView
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.compose.ui.test.ExperimentalTestApi
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.assert
import androidx.compose.ui.test.assertIsFocused
import androidx.compose.ui.test.withKeyDown
import androidx.compose.ui.test.hasSetTextAction
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.onRoot
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performImeAction
import androidx.compose.ui.test.performKeyInput
import androidx.compose.ui.test.performTextInput
import androidx.compose.ui.test.pressKey
import androidx.compose.ui.text.input.ImeAction
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config

/** The composer with the keyboard: its IME action, Enter on a hardware keyboard, focus, and room for the keyboard. */
@RunWith(RobolectricTestRunner::class)
@Config(qualifiers = "w400dp-h800dp")
@OptIn(ExperimentalTestApi::class)
class ComposerKeyboardTest {
    @get:Rule
    val compose = createComposeRule()

    private val sent = mutableListOf<String>()
    private lateinit var view: View

    private fun message(id: Int) = StoredMessage(
        id = "0b7e7c1e-3f7b-4a57-9d3e-%012d".format(id), conversation = "bob", sender = "bob",
        sentAtMillis = 1_767_225_600_000L + id, text = "m$id", sticker = null, icon = null, outgoing = false,
        state = MessageState.RECEIVED, readAtMillis = null,
    )

    private fun show(enterSends: Boolean, messages: List<StoredMessage> = emptyList()) = compose.setContent {
        view = LocalView.current
        ConversationScreen(
            ConversationUiState.Success("bob", messages, HapticIcon.PRESETS, null, null, null, null),
            ConversationActions(onSend = { text, stored -> sent += text; stored() }),
            enterSends = enterSends,
        )
    }

    private fun field() = compose.onNode(hasSetTextAction())

    @Test
    fun enterSendsOn_imeActionIsSend_sendsClearsAndKeepsTheFocus() {
        show(enterSends = true)
        field().assert(SemanticsMatcher.expectValue(SemanticsProperties.ImeAction, ImeAction.Send))
        field().performClick()
        field().performTextInput("on my way")

        field().performImeAction()

        assertEquals(listOf("on my way"), sent)
        assertEquals("", field().fetchSemanticsNode().config[SemanticsProperties.EditableText].text)
        // The keyboard stays for the next message.
        field().assertIsFocused()
    }

    @Test
    fun enterSendsOn_hardwareEnterSendsShiftEnterDoesNot() {
        show(enterSends = true)
        field().performClick()
        field().performTextInput("two")
        field().performKeyInput { withKeyDown(Key.ShiftLeft) { pressKey(Key.Enter) } }
        assertEquals(emptyList<String>(), sent)
        field().performKeyInput { pressKey(Key.Enter) }
        assertEquals(1, sent.size)
        assertTrue(sent.single().startsWith("two"))
    }

    @Test
    fun enterSendsOff_default_enterIsANewLineAndOnlyTheButtonSends() {
        show(enterSends = false)
        field().assert(SemanticsMatcher.expectValue(SemanticsProperties.ImeAction, ImeAction.Default))
        field().performClick()
        field().performTextInput("line one")
        field().performKeyInput { pressKey(Key.Enter) }
        assertEquals(emptyList<String>(), sent)

        compose.onNode(SemanticsMatcher.expectValue(SemanticsProperties.ContentDescription, listOf("Send"))).performClick()
        assertEquals(1, sent.size)
        assertTrue(sent.single().startsWith("line one"))
    }

    /**
     * The keyboard takes the lower 300 dp of the window (its insets dispatched as Android does): the
     * composer moves up above it and the latest message stays visible above the composer.
     */
    @Test
    fun keyboardShown_composerAndLatestMessageStayAboveIt() {
        show(enterSends = false, messages = (1..30).map(::message))
        val windowHeight = compose.onRoot().fetchSemanticsNode().boundsInRoot.bottom
        val keyboardPx = compose.runOnIdle { openKeyboard(view) }
        compose.waitForIdle()

        val composer: Rect = field().fetchSemanticsNode().boundsInRoot
        assertTrue("composer bottom ${composer.bottom} above the keyboard at ${windowHeight - keyboardPx}", composer.bottom <= windowHeight - keyboardPx + 1)
        val latest = compose.onNodeWithText("m30").fetchSemanticsNode().boundsInRoot
        assertTrue("latest message ${latest.bottom} above the composer ${composer.top}", latest.bottom <= composer.top)
    }
}
