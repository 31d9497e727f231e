package org.hapticon.app.feature.chat

import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performTextInput
import org.hapticon.app.data.ChatPreferences
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

@RunWith(RobolectricTestRunner::class)
class ChatListScreenTest {
    @get:Rule
    val compose = createComposeRule()

    @Test
    fun firstRun_noUser_showsAccountFormWithEmulatorBroker() {
        val saved = mutableListOf<Triple<String, String, String>>()
        compose.setContent {
            ChatListScreen(
                ChatListUiState.NeedsAccount(ChatPreferences.DEFAULT_BROKER_URL), emptyList(),
                onSaveAccount = { user, broker, password -> saved += Triple(user, broker, password); null },
                onNewConversation = { null }, onOpen = {}, onAutoPlay = {}, onRendererOverride = {},
            )
        }

        compose.onNodeWithText("tcp://10.0.2.2:1883").assertExists()
        compose.onNodeWithText("User name").performTextInput("alice")
        compose.onNodeWithText("Broker password").performTextInput("s3cret")
        // A password field: masked on screen, and kept out of accessibility read-outs.
        val field = compose.onNodeWithText("Broker password").fetchSemanticsNode().config
        assertEquals(true, androidx.compose.ui.semantics.SemanticsProperties.Password in field)
        assertEquals("••••••", field[androidx.compose.ui.semantics.SemanticsProperties.EditableText].text)
        compose.onNodeWithText("Start chatting").performClick()

        assertEquals(listOf(Triple("alice", "tcp://10.0.2.2:1883", "s3cret")), saved)
    }

    @Test
    fun preferences_default_autoPlayOff() {
        assertEquals(false, ChatPreferences().autoPlay)
    }

    @Test
    fun preferences_toString_neverShowsThePassword() {
        assertEquals(false, ChatPreferences(userName = "alice", brokerPassword = "s3cret").toString().contains("s3cret"))
    }
}
