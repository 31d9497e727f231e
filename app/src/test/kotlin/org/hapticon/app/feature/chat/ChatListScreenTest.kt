package org.hapticon.app.feature.chat

import androidx.compose.runtime.getValue
import androidx.compose.runtime.setValue
import androidx.compose.ui.test.assertIsDisplayed
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.longClick
import androidx.compose.ui.test.assert
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import androidx.compose.ui.test.performTextInput
import androidx.compose.ui.test.performTouchInput
import java.time.ZoneOffset
import java.util.Locale
import androidx.compose.ui.graphics.luminance
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

@RunWith(RobolectricTestRunner::class)
class ChatListScreenTest {
    @get:Rule
    val compose = createComposeRule()

    private val now = 1_767_225_600_000L + 12 * 3_600_000L // 2026-01-01 12:00 UTC
    private val clock = ChatClock(ZoneOffset.UTC, Locale.UK)

    private fun show(state: ChatListUiState.Success, actions: ChatListActions = ChatListActions()) =
        compose.setContent { ChatListScreen(state, actions, clock, now) }

    @Test
    fun firstLaunch_noBrokerPrefilled_savesWhatWasTypedWithThePassword() {
        val saved = mutableListOf<Triple<String, String, String>>()
        compose.setContent { FirstLaunchScreen("", AccountCheck.Idle, onSave = { user, broker, password -> saved += Triple(user, broker, password) }) }

        compose.onNodeWithText("Your user name").performTextInput("alice")
        compose.onNodeWithText("Server address").performTextInput("192.168.1.20")
        compose.onNodeWithText("Password").performTextInput("alice-secret")
        compose.onNodeWithText("Test connection and start").performScrollTo().performClick()

        assertEquals(listOf(Triple("alice", "192.168.1.20", "alice-secret")), saved)
        // The password field is a password field (masked on screen, announced as a password by TalkBack).
        compose.onNodeWithContentDescription("Password")
            .assert(androidx.compose.ui.test.SemanticsMatcher.keyIsDefined(androidx.compose.ui.semantics.SemanticsProperties.Password))
        assertEquals("", ChatPreferences().brokerUrl)
    }

    @Test
    fun firstLaunch_failedTest_showsTheReason() {
        compose.setContent { FirstLaunchScreen("", AccountCheck.Failed("No answer from tcp://10.1.1.1:1883 within 5 s"), onSave = { _, _, _ -> }) }
        compose.onNodeWithText("No answer from tcp://10.1.1.1:1883 within 5 s").performScrollTo().assertIsDisplayed()
    }

    @Test
    fun rows_unreadCounts_showBadgesAndNothingForRead() {
        show(
            ChatListUiState.Success(
                "alice",
                listOf(
                    ConversationSummary("bob", "hi", now - 5 * 60_000, unread = 2),
                    ConversationSummary("carol", "see you", now - 3 * 86_400_000L, unread = 0, lastOutgoing = true),
                    ConversationSummary("dave", "x", now - 30_000, unread = 150),
                ),
            ),
        )
        compose.onNodeWithContentDescription("2 unread", useUnmergedTree = true).assertExists()
        compose.onNodeWithText("99+", useUnmergedTree = true).assertExists()
        compose.onNodeWithContentDescription("0 unread", useUnmergedTree = true).assertDoesNotExist()
        compose.onNodeWithText("5 min").assertExists()
        compose.onNodeWithText("Now").assertExists()
        compose.onNodeWithText("Mon").assertExists()
        compose.onNodeWithText("You: see you").assertExists()
    }

    @Test
    fun preview_lastMessageWithIcon_showsGlyphAndName() {
        val summary = ConversationSummary("bob", "for you", now, 1, lastIconJson = IconJson.encode(HapticIcon.HUG))
        assertEquals("〰 hug · for you", previewOf(summary))
        assertEquals("No messages yet", previewOf(ConversationSummary("bob", null, null, 0)))
    }

    @Test
    fun empty_saysWhatToDoFirst() {
        var invited = 0
        show(ChatListUiState.Success("alice", emptyList()), ChatListActions(onInvite = { invited++ }))
        compose.onNodeWithText("No chats yet").assertIsDisplayed()
        compose.onNodeWithText("Show my invite code").performClick()
        assertEquals(1, invited)
    }

    @Test
    fun delete_fromTheLongPressMenu_waitsForTheSnackbarAndUndoKeepsTheChat() {
        val deleted = mutableListOf<String>()
        show(ChatListUiState.Success("alice", listOf(ConversationSummary("bob", "hi", now, 0))), ChatListActions(onDelete = { deleted += it }))

        compose.onNodeWithText("bob").performTouchInput { longClick() }
        compose.onNodeWithText("Delete").performClick()
        compose.onNodeWithText("Chat with bob deleted").assertIsDisplayed()
        compose.onNodeWithText("bob").assertDoesNotExist()
        compose.onNodeWithText("Undo").performClick()
        compose.waitForIdle()

        assertEquals(emptyList<String>(), deleted)
        compose.onNodeWithText("bob").assertIsDisplayed()
    }

    @Test
    fun delete_notUndone_deletesAfterTheSnackbar() {
        val deleted = mutableListOf<String>()
        show(ChatListUiState.Success("alice", listOf(ConversationSummary("bob", "hi", now, 0))), ChatListActions(onDelete = { deleted += it }))
        compose.onNodeWithText("bob").performTouchInput { longClick() }
        compose.onNodeWithText("Delete").performClick()
        compose.mainClock.advanceTimeBy(10_000)
        compose.waitForIdle()
        assertEquals(listOf("bob"), deleted)
    }

    private var onList by androidx.compose.runtime.mutableStateOf(true)

    /** The list with bob and carol, or (once [onList] is false) another screen; bob deleted from the long-press menu. */
    private fun deleteBobOnALeavableList(deleted: MutableList<String>) {
        val state = ChatListUiState.Success("alice", listOf(ConversationSummary("bob", "hi", now, 0), ConversationSummary("carol", "yo", now, 0)))
        compose.setContent {
            if (onList) ChatListScreen(state, ChatListActions(onDelete = { deleted += it }), clock, now) else androidx.compose.material3.Text("Settings")
        }
        compose.onNodeWithText("bob").performTouchInput { longClick() }
        compose.onNodeWithText("Delete").performClick()
        compose.onNodeWithText("Chat with bob deleted").assertIsDisplayed()
    }

    @Test
    fun delete_thenLeavingTheListBeforeTheSnackbarEnds_deletesAtOnceAndOnlyOnce() {
        val deleted = mutableListOf<String>()
        deleteBobOnALeavableList(deleted)
        assertEquals(emptyList<String>(), deleted)

        onList = false // e.g. Settings opened while the snackbar shows
        compose.waitForIdle()
        assertEquals(listOf("bob"), deleted)
        compose.mainClock.advanceTimeBy(10_000)
        compose.waitForIdle()
        assertEquals(listOf("bob"), deleted)
    }

    @Test
    fun delete_undoneThenLeaving_deletesNothing() {
        val deleted = mutableListOf<String>()
        deleteBobOnALeavableList(deleted)
        compose.onNodeWithText("Undo").performClick()
        compose.waitForIdle()
        onList = false
        compose.waitForIdle()
        assertEquals(emptyList<String>(), deleted)
    }

    @Test
    fun archived_hiddenFromTheListAndCounted() {
        show(
            ChatListUiState.Success(
                "alice",
                listOf(ConversationSummary("bob", "hi", now, 0), ConversationSummary("carol", "yo", now, 0)),
                archived = setOf("carol"),
            ),
        )
        compose.onNodeWithText("carol").assertDoesNotExist()
        compose.onNodeWithText("Archived (1)").performClick()
        compose.onNodeWithText("carol").assertIsDisplayed()
        compose.onNodeWithText("bob").assertDoesNotExist()
    }

    @Test
    fun avatar_initialsAndColour_stableAndReadable() {
        assertEquals("A", initialsOf("alice"))
        assertEquals("BS", initialsOf("bob.smith"))
        assertEquals(avatarColorOf("bob"), avatarColorOf("bob"))
        // White initials keep WCAG AA contrast (4.5:1) on every avatar: 2,000 names cover every hue.
        for (i in 0 until 2_000) {
            val c = avatarColorOf("user$i")
            val contrast = 1.05 / (c.luminance() + 0.05)
            assertTrue("user$i: contrast $contrast", contrast >= 4.5)
        }
    }
}
