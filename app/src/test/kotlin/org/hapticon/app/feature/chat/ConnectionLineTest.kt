package org.hapticon.app.feature.chat

import android.content.Context
import android.os.Looper
import androidx.compose.runtime.collectAsState
import androidx.compose.runtime.getValue
import androidx.compose.ui.test.assertIsDisplayed
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithTag
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performTextInput
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ConnectionState
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

/**
 * The chat screens when messages cannot move: offline, the broker unreachable or refusing, and a peer the broker has
 * never seen. The chats stay on screen (they come from Room); one line under the top bar says why nothing moves.
 */
@RunWith(RobolectricTestRunner::class)
class ConnectionLineTest {
    @get:Rule
    val compose = createComposeRule()

    private val broker = "tcp://192.168.1.20:1883"

    @Test
    fun of_eachConnectionSaysWhatAParticipantNeedsToKnow() {
        val online = ChatConnection.of(ConnectionState.Connected, online = true, broker)
        assertEquals(ChatConnection.Online, online)
        assertNull(online.line())
        // The first attempt under way says nothing: no flicker at every start.
        assertEquals(ChatConnection.Online, ChatConnection.of(ConnectionState.Connecting(null), online = true, broker))
        // Offline wins even over a connection that still reads Connected: its socket went with the network.
        val offline = ChatConnection.of(ConnectionState.Connected, online = false, broker)
        assertEquals("Offline. Messages wait on this phone until it is back online.", offline.line())
        val unreachable = ChatConnection.of(ConnectionState.Connecting("connection refused: nothing accepts connections there"), online = true, broker)
        assertEquals("Can't reach the broker at 192.168.1.20:1883. Messages wait on this phone; trying again.", unreachable.line())
        // Before Android said anything about the network (null), the broker's answer decides.
        assertEquals(unreachable, ChatConnection.of(ConnectionState.Connecting("timeout"), online = null, broker))
        val refused = ChatConnection.of(ConnectionState.Failed("bad user name or password"), online = true, broker)
        assertEquals("The broker refused this account (bad user name or password). Fix it in Settings.", refused.line())
    }

    @Test
    fun chatList_offline_showsTheChatsAndTheLine() {
        val chats = listOf(ConversationSummary("bob", "See you", 1_767_225_600_000L, 2, null))
        compose.setContent { ChatListScreen(ChatListUiState.Success("alice", chats, connection = ChatConnection.Offline), ChatListActions()) }
        compose.onNodeWithText("Offline. Messages wait on this phone until it is back online.").assertIsDisplayed()
        compose.onNodeWithText("bob").assertIsDisplayed()
        compose.onNodeWithText("See you").assertIsDisplayed()
    }

    private fun conversation(connection: ChatConnection, neverConnected: Boolean) = ConversationUiState.Success(
        "carol", listOf(StoredMessage("0b7e7c1e-3f7b-4a57-9d3e-000000000001", "carol", "alice", 1L, "hello?", null, null, true, MessageState.SENT, null)),
        HapticIcon.PRESETS, null, null, null, null, connection = connection, peerNeverConnected = neverConnected,
    )

    @Test
    fun conversation_peerNeverConnected_saysSo_butAConnectionProblemComesFirst() {
        val state = MutableStateFlow(conversation(ChatConnection.Online, neverConnected = true))
        compose.setContent {
            val current by state.collectAsState()
            ConversationScreen(current, ConversationActions())
        }
        compose.onNodeWithText("carol has never connected to this broker. Messages reach them once they do.").assertIsDisplayed()
        compose.onNodeWithText("hello?").assertIsDisplayed()
        // Whether carol ever connected matters less than that nothing moves at all now.
        state.value = conversation(ChatConnection.Unreachable("192.168.1.20:1883"), neverConnected = true)
        compose.onNodeWithText("Can't reach the broker at 192.168.1.20:1883. Messages wait on this phone; trying again.").assertIsDisplayed()
        compose.onNodeWithText("carol has never connected", substring = true).assertDoesNotExist()
        state.value = conversation(ChatConnection.Online, neverConnected = false)
        compose.onNodeWithTag(CONNECTION_LINE_TAG).assertDoesNotExist()
    }

    @Test
    fun newChat_nameTheBrokerNeverSaw_saysSoThenStartAnywayStartsIt() {
        val asked = mutableListOf<Pair<String, Boolean>>()
        compose.setContent {
            ChatListScreen(
                ChatListUiState.Success("alice", emptyList()),
                ChatListActions(onNewChat = { peer, anyway -> asked += peer to anyway; if (anyway) null else NewChatProblem.NeverConnected(peer) }),
            )
        }
        compose.onNodeWithContentDescription("New chat").performClick()
        compose.onNodeWithContentDescription("Their user name").performTextInput("caroll")
        compose.onNodeWithText("Start chat").performClick()
        compose.onNodeWithText(NewChatProblem.NeverConnected("caroll").message).assertIsDisplayed()
        compose.onNodeWithText("Start anyway").performClick()
        assertEquals(listOf("caroll" to false, "caroll" to true), asked)
        compose.onNodeWithText("Start anyway").assertDoesNotExist() // the dialog closed
    }

    @Test
    fun startConversation_checksTheDirectoryOnlyOnceItIsKnown() {
        val context = ApplicationProvider.getApplicationContext<Context>()
        val db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).allowMainThreadQueries().build()
        try {
            val repository = OfflineFirstChatRepository(db)
            val known = MutableStateFlow<Set<String>?>(null)
            val viewModel = ChatListViewModel(repository, InMemoryChatSettings(ChatPreferences(userName = "alice")), { _, _, _ -> null }, knownUsers = known)
            val opened = mutableListOf<String>()
            // Not known yet (offline, still connecting): the chat starts; its screen says so once known.
            assertNull(viewModel.startConversation("dana", onStarted = { opened += it }))
            known.value = setOf("alice", "bob")
            assertEquals(NewChatProblem.NeverConnected("carol"), viewModel.startConversation("carol", onStarted = { opened += it }))
            assertNull(viewModel.startConversation("bob", onStarted = { opened += it }))
            assertNull(viewModel.startConversation("carol", evenIfUnknown = true, onStarted = { opened += it }))
            // Each start stores the conversation (on Room's thread), then opens it (on the main thread).
            val deadline = System.nanoTime() + 5_000_000_000L
            while (opened.size < 3 && System.nanoTime() < deadline) {
                shadowOf(Looper.getMainLooper()).idle()
                Thread.sleep(10)
            }
            assertEquals(setOf("dana", "bob", "carol"), opened.toSet())
            val peers = runBlocking { repository.conversations().first() }.map { it.peer }.toSet()
            assertEquals(setOf("dana", "bob", "carol"), peers)
        } finally {
            db.close()
        }
    }
}
