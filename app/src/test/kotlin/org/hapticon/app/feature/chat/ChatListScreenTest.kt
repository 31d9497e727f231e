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
        val saved = mutableListOf<Pair<String, String>>()
        compose.setContent {
            ChatListScreen(
                ChatListUiState.NeedsAccount(ChatPreferences.DEFAULT_BROKER_URL), emptyList(),
                onSaveAccount = { user, broker -> saved += user to broker; null },
                onNewConversation = { null }, onOpen = {}, onAutoPlay = {}, onRendererOverride = {},
            )
        }

        compose.onNodeWithText("tcp://10.0.2.2:1883").assertExists()
        compose.onNodeWithText("User name").performTextInput("alice")
        compose.onNodeWithText("Start chatting").performClick()

        assertEquals(listOf("alice" to "tcp://10.0.2.2:1883"), saved)
    }

    @Test
    fun preferences_default_autoPlayOff() {
        assertEquals(false, ChatPreferences().autoPlay)
    }
}
