package org.hapticon.app.feature.chat

import org.hapticon.app.ui.Sticker
import androidx.compose.ui.test.hasSetTextAction
import org.hapticon.app.playback.lastUsage
import org.hapticon.core.platform.VibrationUsage
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performTextInput
import androidx.compose.ui.test.performTextReplacement
import androidx.compose.ui.test.onAllNodesWithText
import org.hapticon.messaging.MessageLimits
import androidx.compose.ui.test.performTouchInput
import androidx.compose.ui.test.longClick
import androidx.compose.ui.test.SemanticsMatcher
import androidx.compose.ui.test.assert
import androidx.compose.ui.test.SemanticsNodeInteraction
import androidx.compose.ui.semantics.SemanticsProperties
import androidx.room.Room
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.lastVibration
import org.hapticon.core.HapticIcon
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

private fun SemanticsNodeInteraction.assertStateDescription(expected: String) =
    this.assert(SemanticsMatcher.expectValue(SemanticsProperties.StateDescription, expected))

/** The composer through its ViewModel into Room and the outbox: what a user's tap actually stores. */
@RunWith(RobolectricTestRunner::class)
@Config(qualifiers = "w400dp-h1600dp")
class ComposerSendTest {
    @get:Rule
    val compose = createComposeRule()

    private val fixture = ComposerFixture(compose)
    @Volatile private var wakes = 0

    @Before
    fun setUp() = fixture.show(onSent = { wakes++ })

    @After
    fun tearDown() = fixture.close()

    private fun stored() = fixture.stored()

    @Test
    fun textWithIcon_longPressPreviewsTapChoosesAndSendStoresBothAndQueuesIt() {
        compose.onNode(composerIconChip("knock")).performTouchInput { longClick() }
        compose.waitUntil(5_000) { lastVibration(fixture.vibrator) != null } // rendered off the main thread, then played
        // A long press previews: the knock went to the vibrator, and nothing was chosen.
        // The processing knock (the default model): 10 ms at 175, 10 ms at 111, then 250 ms off, three times.
        assertEquals(RecordedVibration(listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), listOf(175, 111, 0, 175, 111, 0, 175, 111)), lastVibration(fixture.vibrator))
        assertEquals(VibrationUsage.TOUCH, lastUsage(fixture.vibrator))
        compose.onNode(composerIconChip("knock")).assertStateDescription("not selected")
        compose.onNode(composerIconChip("knock")).performClick()
        compose.onNode(composerIconChip("knock")).assertStateDescription("selected")
        compose.onNode(hasSetTextAction()).performTextInput("feel this")
        compose.onNodeWithContentDescription("Send").performClick()
        compose.waitUntil(5_000) { stored().isNotEmpty() }

        val message = stored().single()
        assertEquals("feel this", message.text)
        assertEquals(HapticIcon.KNOCK, message.icon)
        assertEquals(null, message.sticker)
        assertEquals(MessageState.SENDING, message.state)
        assertEquals(listOf(message.id), runBlocking { fixture.db.outboxDao().pending() }.map { it.messageId })
        // The outbox sender is woken once the message is stored.
        compose.waitUntil(5_000) {
            // The ViewModel resumes on the main looper once Room's transaction is done.
            shadowOf(android.os.Looper.getMainLooper()).idle()
            wakes == 1
        }
    }

    @Test
    fun stickerWithIcon_sendStoresTheStickerAndTheIcon() {
        compose.onNodeWithContentDescription("Sticker Hug").performClick()
        compose.onNode(composerIconChip("hug")).performClick()
        compose.onNodeWithContentDescription("Send").performClick()
        compose.waitUntil(5_000) { stored().isNotEmpty() }

        val message = stored().single()
        assertEquals("", message.text)
        assertEquals("hug", message.sticker)
        assertEquals(HapticIcon.HUG, message.icon)
    }

    /** A send that cannot be stored (too long) keeps what was typed under the reason; once fixed, it goes and the field empties. */
    @Test
    fun sendFails_textTooLong_keepsTheTextAndSaysWhy_thenSendsOnceShortened() {
        val long = "a".repeat(MessageLimits.MAX_TEXT_LENGTH + 1)
        compose.onNode(hasSetTextAction()).performTextInput(long)
        compose.onNodeWithContentDescription("Send").performClick()
        compose.waitUntil(5_000) { compose.onAllNodesWithText("exceed the limit", substring = true).fetchSemanticsNodes().isNotEmpty() }
        assertEquals(long, fieldText())
        assertEquals(emptyList<Any>(), stored())

        compose.onNode(hasSetTextAction()).performTextReplacement("short")
        compose.onNodeWithContentDescription("Send").performClick()
        compose.waitUntil(5_000) { stored().isNotEmpty() }
        assertEquals("short", stored().single().text)
        compose.waitUntil(5_000) { fieldText().isEmpty() }
    }

    private fun fieldText(): String = compose.onNode(hasSetTextAction()).fetchSemanticsNode().config[SemanticsProperties.EditableText].text
}
