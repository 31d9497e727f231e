package org.hapticon.app.feature.chat

import androidx.activity.ComponentActivity
import androidx.compose.ui.test.junit4.createAndroidComposeRule
import androidx.lifecycle.Lifecycle
import java.util.concurrent.CopyOnWriteArrayList
import kotlin.coroutines.EmptyCoroutineContext
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.playback.usageVibrator
import org.hapticon.app.sync.ChatComponent
import org.hapticon.app.sync.ChatSync
import org.hapticon.app.sync.TestMessenger
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.VibrationRateLimiter
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/**
 * "Read" only while the conversation is on screen: the real [ConversationRoute] in an activity whose lifecycle the test
 * moves as Android does when the user leaves the app with the chat open (RESUMED → STARTED) and comes back.
 */
@RunWith(RobolectricTestRunner::class)
class ReadOnScreenTest {
    @get:Rule val compose = createAndroidComposeRule<ComponentActivity>()

    private val fixture = ComposerFixture(compose, allowMainThreadQueries = false)
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val messenger = TestMessenger("alice")
    private val settings = InMemoryChatSettings(ChatPreferences(userName = "alice"))
    private val player = AdaptiveHapticPlayer(usageVibrator(fixture.vibrator), { fixture.device }, { null }, renderContext = EmptyCoroutineContext)
    private val sync = ChatSync(
        fixture.repository, fixture.repository, settings, { _, _, _ -> messenger }, player,
        VibrationRateLimiter(Clock.MONOTONIC), { user -> RendererChoice.capabilitiesOf(user, fixture.device, null) }, scope,
    )
    private val component = ChatComponent(
        fixture.repository, RoomIconRepository(fixture.db.iconDao()), settings, sync, player, { fixture.device },
    )
    private val notified = CopyOnWriteArrayList<String>()

    @After
    fun tearDown() {
        runBlocking { scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin() }
        fixture.close()
    }

    private fun deliver(id: String) = messenger.deliver(InboxEvent.MessageReceived(ChatMessage(id, "bob", fixture.now, "hi $id")))

    private fun state(id: String) = runBlocking { fixture.repository.messages("bob").first().single { it.id == id }.state }

    private fun readReceipts() = messenger.sentReceipts.value.filter { it.second.state == ReceiptState.READ }.map { it.second.messageId }

    private fun awaitUntil(what: String, condition: () -> Boolean) {
        val deadline = System.currentTimeMillis() + 5_000
        while (!condition()) {
            if (System.currentTimeMillis() > deadline) throw AssertionError("timed out waiting for $what")
            compose.waitForIdle()
            Thread.sleep(20)
        }
    }

    @Test
    fun leavingTheAppWithTheChatOpen_laterMessagesAreNeitherReadNorKeptFromNotifying() {
        sync.onIncoming = { message, _ -> notified += message.id }
        sync.start()
        runBlocking { withTimeout(5_000) { messenger.state.first { it == ConnectionState.Connected } } }
        compose.setContent { ConversationRoute(component, "bob", onBack = {}, onEditIcon = {}) }
        compose.waitForIdle()

        // On screen (RESUMED): read at once, with the read receipt, and no notification.
        val seen = "0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c01"
        deliver(seen)
        awaitUntil("read receipt") { readReceipts() == listOf(seen) }
        assertEquals(MessageState.READ, state(seen))
        assertEquals(emptyList<String>(), notified.toList())

        // The user goes to another app (or the screen turns off): the activity is paused with the chat still composed.
        compose.activityRule.scenario.moveToState(Lifecycle.State.STARTED)
        val unseen = "0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c02"
        deliver(unseen)
        assertEquals(MessageState.RECEIVED, state(unseen))
        assertEquals(listOf(unseen), notified.toList())
        assertEquals(listOf(seen), readReceipts())

        // Back in the app: now it is read.
        compose.activityRule.scenario.moveToState(Lifecycle.State.RESUMED)
        awaitUntil("read receipt on return") { readReceipts() == listOf(seen, unseen) }
        assertEquals(MessageState.READ, state(unseen))
    }
}
