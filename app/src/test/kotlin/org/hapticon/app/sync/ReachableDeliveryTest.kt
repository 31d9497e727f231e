package org.hapticon.app.sync

import kotlin.coroutines.EmptyCoroutineContext
import org.hapticon.app.playback.usageVibrator
import android.Manifest
import android.app.Application
import android.app.NotificationManager
import android.content.Context
import android.os.Vibrator
import androidx.core.app.NotificationCompat
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.playback.lastVibration
import org.hapticon.app.playback.lastUsage
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.VibrationRateLimiter
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

/**
 * "Reachable in the pocket" end to end: no activity exists; the chat sync holds a real MQTT session to the
 * embedded broker; bob publishes from another client. Each message is stored once, announced once in a
 * MessagingStyle notification and felt once (autoplay), and bob gets a felt receipt; after the broker
 * restarts the session comes back by itself and the next message arrives the same way.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class ReachableDeliveryTest {
    @get:Rule
    val temp = TemporaryFolder()

    // Every messenger ChatSync makes is this phone's: one session across reconnections.
    private val phoneDevice = DeviceId.generate()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val vibrator = context.getSystemService(Vibrator::class.java)
    private val notifications = context.getSystemService(NotificationManager::class.java)
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
    private val fastReconnect = RetryPolicy(initialDelayMillis = 50, maxDelayMillis = 500, jitter = 0.0)
    private lateinit var broker: BrokerProcess
    private lateinit var db: HapticonDatabase
    private lateinit var repository: OfflineFirstChatRepository
    private lateinit var sync: ChatSync
    private lateinit var bob: MqttMessenger
    private val bobInbox = CopyOnWriteArrayList<InboxEvent>()

    @Before
    fun setUp() = runBlocking {
        shadowOf(vibrator).setHasAmplitudeControl(true)
        shadowOf(context as Application).grantPermissions(Manifest.permission.POST_NOTIFICATIONS)
        broker = BrokerProcess(temp.newFolder("broker"), BrokerProcess.freePort()).also { it.start() }
        val address = BrokerAddress(EmbeddedBroker.HOST, broker.port)
        db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).build()
        repository = OfflineFirstChatRepository(db)
        val settings = InMemoryChatSettings(ChatPreferences(userName = "alice", brokerUrl = address.toString(), autoPlay = true, brokerPassword = "alice-secret"))
        sync = ChatSync(
            repository, repository, settings,
            { user, url, password -> MqttMessenger(MqttSettings(BrokerAddress.parse(url), user, password, phoneDevice, reconnectPolicy = fastReconnect)) },
            // Rendered on the calling thread: this test is about delivery (threading: MainThreadWorkTest).
            AdaptiveHapticPlayer(usageVibrator(vibrator), { device }, { null }, renderContext = EmptyCoroutineContext), VibrationRateLimiter(Clock.MONOTONIC),
            { user -> RendererChoice.capabilitiesOf(user, device, null) }, scope,
        )
        val notifier = MessageNotifier(context) { "alice" }
        sync.onIncoming = { message, alert -> notifier.show(message, alert) }
        sync.start()
        await(sync.connection) { it == ConnectionState.Connected }
        bob = MqttMessenger(MqttSettings(address, "bob", "bob-secret", DeviceId.generate(), reconnectPolicy = fastReconnect))
        bob.connect(InboxListener { bobInbox += it })
    }

    @After
    fun tearDown() = runBlocking {
        if (::bob.isInitialized) runCatching { bob.disconnect() }
        scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin()
        if (::db.isInitialized) db.close()
        if (::broker.isInitialized) broker.stop()
    }

    private fun <T> await(flow: Flow<T>, predicate: (T) -> Boolean): T = runBlocking { withTimeout(20_000) { flow.first(predicate) } }

    private fun awaitTrue(what: String, condition: () -> Boolean) = runBlocking {
        kotlinx.coroutines.withTimeoutOrNull(20_000) { while (!condition()) delay(20) } ?: throw AssertionError("timed out waiting for $what")
    }

    /** The lines of bob's conversation notification. */
    private fun lines(): List<String> {
        val posted = shadowOf(notifications).getNotification("bob", MessageNotifier.NOTIFICATION_ID) ?: return emptyList()
        val style = NotificationCompat.MessagingStyle.extractMessagingStyleFromNotification(posted) ?: return emptyList()
        return style.messages.map { it.text.toString() }
    }

    private fun receipts(state: ReceiptState) =
        bobInbox.filterIsInstance<InboxEvent.ReceiptReceived>().filter { it.receipt.state == state }.map { it.receipt.messageId }

    @Test
    fun messageWhileNoScreen_notifiedFeltAndReceiptedOnce_evenAcrossABrokerRestart() = runBlocking {
        val first = ChatMessage.compose("bob", "feel this", null, HapticIcon.KNOCK, Clock.SYSTEM)
        bob.send("alice", first)

        awaitTrue("notification") { lines().isNotEmpty() }
        assertEquals(listOf("〰 knock · feel this"), lines())
        val posted = shadowOf(notifications).getNotification("bob", MessageNotifier.NOTIFICATION_ID)
        // On bob's icon channel, which neither rings nor vibrates: the knock that follows is the message's vibration.
        assertEquals("icons-bob", posted.channelId)
        assertEquals(listOf("Reply", "Mark as read", "Feel knock again"), posted.actions.map { it.title.toString() })
        // Autoplay felt it through the normal renderer: the knock's exact amplitude steps, as a received communication.
        awaitTrue("the knock") { lastVibration(vibrator) != null }
        assertEquals(RecordedVibration(listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), listOf(175, 111, 0, 175, 111, 0, 175, 111)), lastVibration(vibrator))
        assertEquals(VibrationUsage.COMMUNICATION_REQUEST, lastUsage(vibrator))
        awaitTrue("felt receipt") { receipts(ReceiptState.FELT) == listOf(first.id) }

        // MQTT is at-least-once: the same message again is stored, shown and felt no second time.
        bob.send("alice", first)
        awaitTrue("second delivered receipt") { receipts(ReceiptState.DELIVERED).size == 2 }
        assertEquals(listOf("〰 knock · feel this"), lines())
        assertEquals(listOf(first.id), receipts(ReceiptState.FELT))
        assertEquals(1, repository.messages("bob").first().size)

        // The broker restarts: the session returns by itself and the next message arrives the same way.
        broker.restart()
        val second = ChatMessage.compose("bob", "still there?", null, HapticIcon.HIT, Clock.SYSTEM)
        withTimeout(20_000) {
            while (true) {
                try {
                    bob.send("alice", second)
                    break
                } catch (e: MessagingException) {
                    bob.state.first { it == ConnectionState.Connected }
                }
            }
        }
        awaitTrue("second notification line") { lines().size == 2 }
        assertEquals(listOf("〰 knock · feel this", "〰 hit · still there?"), lines())
        awaitTrue("second felt receipt") { receipts(ReceiptState.FELT) == listOf(first.id, second.id) }
        assertEquals(listOf(MessageState.RECEIVED, MessageState.RECEIVED), repository.messages("bob").first().map { it.state })
    }
}
