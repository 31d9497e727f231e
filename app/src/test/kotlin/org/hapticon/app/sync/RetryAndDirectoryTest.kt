package org.hapticon.app.sync

import android.content.Context
import android.os.Looper
import android.os.Vibrator
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.RoomIconRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.feature.chat.ConversationViewModel
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RendererChoice
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.VibrationRateLimiter
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import kotlin.coroutines.EmptyCoroutineContext

/**
 * Two things the chat screens rely on the sync for: a message that could not be sent is sent again, as the same row,
 * when the user taps retry; and the broker's directory of users (their retained capabilities) is known only once the
 * broker has sent all of it. The clock is the test's: the outbox's own retries wait for it, so only the tap resends.
 */
@RunWith(RobolectricTestRunner::class)
class RetryAndDirectoryTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
    private val db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).build()
    @Volatile private var now = 1_700_000_000_000L
    private val repository = OfflineFirstChatRepository(db, clock = { now })
    private val messenger = TestMessenger("alice")
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val player = AdaptiveHapticPlayer(org.hapticon.app.playback.usageVibrator(context.getSystemService(Vibrator::class.java)), { device }, { null }, renderContext = EmptyCoroutineContext)
    private val sync = ChatSync(
        repository, repository, InMemoryChatSettings(ChatPreferences(userName = "alice")), { _, _, _ -> messenger },
        player, VibrationRateLimiter(Clock { now }), { user -> RendererChoice.capabilitiesOf(user, device, null) }, scope,
        clock = { now }, retryPolicy = RetryPolicy(initialDelayMillis = 10, maxDelayMillis = 10, jitter = 0.0),
    ).also { it.start() }

    @After
    fun tearDown() {
        runBlocking { scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin() }
        db.close()
    }

    private fun <T> await(flow: Flow<T>, predicate: (T) -> Boolean): T = runBlocking { withTimeout(5_000) { flow.first(predicate) } }

    private fun caps(user: String) = Capabilities(user, RendererKind.AMPLITUDE_WAVEFORM, amplitudeControl = true, apiLevel = 35)

    /** Lets the outbox fail three attempts (the repository's threshold for "not sent"), each due by the test's clock. */
    private fun failThreeTimes() {
        for (attempt in 1..3) {
            await(db.outboxDao().pendingStream()) { it.single().attempts >= attempt }
            if (attempt < 3) {
                now += 10
                sync.wake()
            }
        }
        await(repository.messages("bob")) { it.single().state == MessageState.FAILED }
    }

    @Test
    fun failedMessage_retryTapped_theSameRowIsSentWithItsIdAndShowsSent() = runBlocking {
        await(messenger.state) { it == ConnectionState.Connected }
        messenger.failing = true
        val message = repository.send("alice", "bob", "are you there?")
        sync.wake()
        // Three failed attempts (the repository's threshold), each due once the test's clock reaches it.
        failThreeTimes()
        messenger.failing = false // the outbox's own next attempt waits for the test's clock, which stands still: only the tap sends

        val viewModel = ConversationViewModel(
            "bob", { "alice" }, repository, RoomIconRepository(db.iconDao()), player, MutableStateFlow(emptyMap()), sync::wake,
        )
        viewModel.retry(repository.messages("bob").first().single())
        shadowOf(Looper.getMainLooper()).idle()

        val sent = await(messenger.sentMessages) { it.isNotEmpty() }.single()
        assertEquals("bob", sent.first)
        assertEquals(true, sent.second.contains("\"id\":\"${message.id}\""))
        val rows = await(repository.messages("bob")) { it.single().state == MessageState.SENT }
        assertEquals(listOf(message.id), rows.map { it.id })
        assertEquals("are you there?", rows.single().text)
    }

    @Test
    fun retryNow_failedMessage_showsSendingAgainUntilTheBrokerHasIt() = runBlocking {
        messenger.failing = true
        await(messenger.state) { it == ConnectionState.Connected }
        val message = repository.send("alice", "bob", "later")
        sync.wake()
        failThreeTimes()
        // The link is down while the user taps: the message shows the clock, not the red line, until an attempt ends.
        messenger.setConnection(ConnectionState.Connecting(null))
        repository.retryNow(message.id)
        await(repository.messages("bob")) { it.single().state == MessageState.SENDING }
        // Back, but the broker still refuses: red again, still one row.
        messenger.setConnection(ConnectionState.Connected)
        await(repository.messages("bob")) { it.single().state == MessageState.FAILED }
        assertEquals(1, repository.messages("bob").first().size)
    }

    @Test
    fun knownUsers_completeOnlyOnceTheLiveCopyOfOwnCapabilitiesFollowsTheRetainedOnes() {
        await(messenger.state) { it == ConnectionState.Connected }
        assertNull(sync.knownUsers.value)
        messenger.deliver(InboxEvent.CapabilitiesReceived(caps("bob"), retained = true))
        // Alice's own stored copy from her last connection is part of the directory, not its end.
        messenger.deliver(InboxEvent.CapabilitiesReceived(caps("alice"), retained = true))
        assertNull(sync.knownUsers.value)
        messenger.deliver(InboxEvent.CapabilitiesReceived(caps("alice"), retained = false))
        assertEquals(setOf("alice", "bob"), sync.knownUsers.value)
        // Carol connects for the first time later: her publish arrives live and she joins.
        messenger.deliver(InboxEvent.CapabilitiesReceived(caps("carol"), retained = false))
        assertEquals(setOf("alice", "bob", "carol"), sync.knownUsers.value)
    }

    @Test
    fun knownUsers_newSession_unknownUntilItsOwnDirectoryIsComplete() {
        await(messenger.state) { it == ConnectionState.Connected }
        messenger.deliver(InboxEvent.CapabilitiesReceived(caps("alice"), retained = false))
        assertEquals(setOf("alice"), sync.knownUsers.value)
        // The network moved: a fresh messenger subscribes afresh, possibly to a broker that knows other users.
        sync.networkAvailable("100")
        sync.networkAvailable("101")
        await(sync.knownUsers) { it == null }
    }
}
