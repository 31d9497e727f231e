package org.hapticon.app.navigation

import android.content.Intent
import android.net.ConnectivityManager
import androidx.compose.ui.geometry.Rect
import androidx.compose.ui.test.assertIsDisplayed
import androidx.compose.ui.test.hasClickAction
import androidx.compose.ui.test.hasSetTextAction
import androidx.compose.ui.test.hasText
import androidx.compose.ui.test.junit4.createEmptyComposeRule
import androidx.compose.ui.test.onNodeWithTag
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.onRoot
import androidx.compose.ui.test.performClick
import org.hapticon.app.feature.chat.MESSAGE_LIST_TAG
import org.hapticon.app.feature.chat.openKeyboard
import androidx.test.core.app.ActivityScenario
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.delay
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeoutOrNull
import org.hapticon.app.HapticonApplication
import org.hapticon.app.MainActivity
import org.hapticon.app.sync.MessageNotifier
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.ConnectionState
import org.hapticon.app.data.TestAndroidKeyStore
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Before
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config
import org.robolectric.shadows.ShadowNetwork

/**
 * The chat screens in the real app frame ([MainActivity]: edge to edge, `adjustResize`, the application's own chat
 * component) on a small phone: 360 dp wide, at the default and the largest font scale (2.0, the largest Android 14+
 * offers). Inside a conversation the tab bar is gone, as in Signal and Google Messages; with the keyboard up (its
 * insets dispatched to the window's decor view, as Android dispatches them) the composer sits on the keyboard and the
 * latest message stays visible above it. With the broker unreachable or the phone offline, the chats are there all
 * the same, with a line saying why nothing moves.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35], qualifiers = "w360dp-h780dp")
class ChatFrameTest {
    @get:Rule
    val compose = createEmptyComposeRule()

    private val app = ApplicationProvider.getApplicationContext<HapticonApplication>()
    private val chat = app.container.chat!!

    // The account seals end to end by default: its keys are wrapped by the Android Keystore, which Robolectric lacks.
    @Before
    fun installKeystore() = TestAndroidKeyStore.install()

    @After
    fun uninstallKeystore() = TestAndroidKeyStore.uninstall()

    private fun tabBar() = compose.onNode(hasText("Icons") and hasClickAction())

    /** An account on [brokerUrl] ("": none, nothing connects) and twelve messages from bob. */
    private fun aliceWithTwelveMessagesFromBob(brokerUrl: String = "") {
        chat.settings.update { it.copy(userName = "alice", brokerUrl = brokerUrl) }
        runBlocking {
            for (n in 1..12) chat.repository.receive(ChatMessage.compose("bob", "message $n", clock = { 1_767_225_600_000L + n * 60_000L }))
        }
    }

    /** Opens the app on bob's conversation, as tapping his notification does. */
    private fun openBob(): ActivityScenario<MainActivity> {
        val open = Intent(app, MainActivity::class.java).setAction(MessageNotifier.ACTION_OPEN_CHAT).putExtra(MessageNotifier.EXTRA_PEER, "bob")
        return ActivityScenario.launch<MainActivity>(open).also {
            compose.waitUntil(10_000) { compose.onAllNodes(hasSetTextAction()).fetchSemanticsNodes().isNotEmpty() }
        }
    }

    private fun keyboardUp_composerAndLatestMessageAboveIt(fontScale: Float) {
        aliceWithTwelveMessagesFromBob()
        openBob().use { scenario ->
            scenario.onActivity { assertEquals(fontScale, it.resources.configuration.fontScale) }
            tabBar().assertDoesNotExist()
            compose.onNodeWithText("message 12").assertIsDisplayed()

            val windowHeight = compose.onRoot().fetchSemanticsNode().boundsInRoot.bottom
            var keyboardPx = 0
            scenario.onActivity { activity -> keyboardPx = openKeyboard(activity.window.decorView) }
            compose.waitForIdle()

            val field: Rect = compose.onNode(hasSetTextAction()).fetchSemanticsNode().boundsInRoot
            val keyboardTop = windowHeight - keyboardPx
            // On the keyboard: not under it, and not left floating where it was (the composer's padding apart).
            assertTrue("the composer (bottom ${field.bottom}) sits on the keyboard (top $keyboardTop)", field.bottom in (keyboardTop - 100)..(keyboardTop + 1))
            // The latest message whole: inside what is left of the message list, which ends above the composer.
            val latest = compose.onNodeWithText("message 12").fetchSemanticsNode().boundsInRoot
            val list = compose.onNodeWithTag(MESSAGE_LIST_TAG).fetchSemanticsNode().boundsInRoot
            assertTrue("the latest message (bottom ${latest.bottom}) is above the composer (top ${field.top})", latest.bottom <= field.top)
            assertTrue("the latest message (${latest.top}..${latest.bottom}) is whole in the list (${list.top}..${list.bottom})", latest.top >= list.top && latest.bottom <= list.bottom)

            // Back to the list: the tab bar is there again.
            scenario.onActivity { it.onBackPressedDispatcher.onBackPressed() }
            compose.waitForIdle()
            tabBar().assertIsDisplayed()
        }
    }

    @Test
    fun conversation_defaultFont_noTabBar_keyboardUp_composerAndLatestMessageAboveIt() = keyboardUp_composerAndLatestMessageAboveIt(1.0f)

    @Test
    @Config(fontScale = 2.0f)
    fun conversation_largestFont_noTabBar_keyboardUp_composerAndLatestMessageAboveIt() = keyboardUp_composerAndLatestMessageAboveIt(2.0f)

    /**
     * Nothing listens where the broker should be (the real MQTT client is refused): the conversation and the list show
     * bob's messages from Room, each with the line naming the broker; then Android says the network is gone.
     */
    @Test
    fun brokerUnreachableThenOffline_chatsShowWithALineSayingWhy() {
        aliceWithTwelveMessagesFromBob(brokerUrl = "tcp://127.0.0.1:1")
        runBlocking {
            withTimeoutOrNull(20_000) { while ((chat.sync.connection.value as? ConnectionState.Connecting)?.lastFailure == null) delay(20) }
                ?: throw AssertionError("still ${chat.sync.connection.value}")
        }
        openBob().use {
            val unreachable = "Can't reach the broker at 127.0.0.1:1. Messages wait on this phone; trying again."
            compose.waitUntil(10_000) { compose.onAllNodes(hasText(unreachable)).fetchSemanticsNodes().isNotEmpty() }
            compose.onNodeWithText("message 12").assertIsDisplayed()

            it.onActivity { activity -> activity.onBackPressedDispatcher.onBackPressed() }
            compose.waitUntil(10_000) { compose.onAllNodes(hasText("bob")).fetchSemanticsNodes().isNotEmpty() }
            compose.onNodeWithText(unreachable).assertIsDisplayed()
            compose.onNodeWithText("message 12").assertIsDisplayed() // bob's row's preview

            // Android's default network goes, with none to replace it.
            val connectivity = app.getSystemService(ConnectivityManager::class.java)
            val network = ShadowNetwork.newInstance(100)
            shadowOf(connectivity).networkCallbacks.forEach { callback -> callback.onAvailable(network) }
            shadowOf(connectivity).networkCallbacks.forEach { callback -> callback.onLost(network) }
            compose.waitUntil(10_000) { compose.onAllNodes(hasText("Offline. Messages wait on this phone until it is back online.")).fetchSemanticsNodes().isNotEmpty() }
            compose.onNodeWithText("bob").performClick()
            compose.waitUntil(10_000) { compose.onAllNodes(hasSetTextAction()).fetchSemanticsNodes().isNotEmpty() }
            compose.onNodeWithText("Offline. Messages wait on this phone until it is back online.").assertIsDisplayed()
            compose.onNodeWithText("message 12").assertIsDisplayed()
        }
    }
}
