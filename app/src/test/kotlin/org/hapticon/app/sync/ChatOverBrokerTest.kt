package org.hapticon.app.sync

import android.Manifest
import android.app.NotificationManager
import android.app.RemoteInput
import android.content.Intent
import android.os.Bundle
import android.os.Looper
import androidx.test.core.app.ApplicationProvider
import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.delay
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.withTimeoutOrNull
import android.database.sqlite.SQLiteDatabase
import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.datatypes.MqttQos
import java.util.concurrent.TimeUnit
import org.hapticon.app.HapticonApplication
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.Topics
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.Identity
import org.hapticon.testing.TestKeyPins
import org.hapticon.app.data.TestAndroidKeyStore
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

/**
 * The app's own chat wiring (the application's container: settings, sync, notifier, probe and the
 * notification's receiver) against the embedded broker in a child JVM, with bob on another client. End to end
 * as shipped: alice's keys are wrapped by a Keystore key (the in-memory test provider), bob seals too.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
class ChatOverBrokerTest {
    @get:Rule
    val temp = TemporaryFolder()

    private val app = ApplicationProvider.getApplicationContext<HapticonApplication>()
    private val chat = app.container.chat!!
    private val notifications = app.getSystemService(NotificationManager::class.java)
    private lateinit var broker: BrokerProcess
    private lateinit var address: BrokerAddress
    private var bob: MqttMessenger? = null

    @Before
    fun setUp() {
        TestAndroidKeyStore.install()
        shadowOf(app).grantPermissions(Manifest.permission.POST_NOTIFICATIONS)
        broker = BrokerProcess(temp.newFolder("broker"), BrokerProcess.freePort()).also { it.start() }
        address = BrokerAddress(EmbeddedBroker.HOST, broker.port)
    }

    @After
    fun tearDown() = runBlocking {
        bob?.let { runCatching { it.disconnect() } }
        // No account: the application's sync ends its session before the broker goes.
        chat.settings.update { it.copy(userName = null) }
        withTimeoutOrNull(10_000) { chat.sync.connection.first { it != ConnectionState.Connected } }
        broker.stop()
        TestAndroidKeyStore.uninstall()
    }

    /** bob on his own client, sealing end to end with keys of his own. */
    private fun sealingBob(): MqttMessenger {
        val fast = RetryPolicy(initialDelayMillis = 50, maxDelayMillis = 500, jitter = 0.0)
        return MqttMessenger(MqttSettings(address, "bob", "bob-secret", DeviceId.generate(), reconnectPolicy = fast), EndToEnd(Identity.generate("bob"), TestKeyPins())).also { bob = it }
    }

    /** Sends as soon as [from] has the recipient's key (its retained key arrives just after connecting). */
    private suspend fun sendWhenKeyKnown(from: MqttMessenger, to: String, message: ChatMessage) {
        val deadline = System.nanoTime() + 20_000_000_000L
        while (true) {
            try {
                return from.send(to, message)
            } catch (e: MessagingException) {
                if (System.nanoTime() > deadline) throw e
                delay(20)
            }
        }
    }

    /** This phone's client id for alice: `alice:` and the device id the app keeps (ChatComponent.mqttMessenger). */
    private fun phoneSession(): String = "alice:" + DeviceId.loadOrCreate(java.io.File(app.filesDir, "mqtt-devices/alice")).value

    private fun awaitTrue(what: String, condition: suspend () -> Boolean) = runBlocking {
        withTimeoutOrNull(20_000) { while (!condition()) delay(20) }
            ?: throw AssertionError("timed out waiting for $what; alice's rows: ${chat.repository.messages("bob").first()}, connection ${chat.sync.connection.value}")
    }

    /**
     * The app's probe on its own settings and sync, with more time than the app's 5 s: a cold test JVM on a
     * busy machine can take longer for a broker that does answer.
     */
    private fun probe(password: String): String? =
        runBlocking { ChatComponent.probeBroker(chat.settings, chat.sync, "alice", address, password, timeoutMillis = 30_000) }

    @Test
    fun probe_answeringBroker_savesTheAccountAndLeavesOnlyTheUsersOwnSession() {
        val problem = probe("alice-secret")

        assertNull(problem)
        assertEquals("alice", chat.settings.preferences.value.userName)
        // The probe was this phone's own persistent session of the user, now in use; nothing else.
        assertEquals(mapOf(phoneSession() to true), broker.sessions())
    }

    @Test
    fun probe_wrongPassword_savesNothingAndLeavesNoSession() {
        val problem = probe("guess")

        assertEquals("The broker at $address refused the connection: bad user name or password", problem)
        assertNull(chat.settings.preferences.value.userName)
        assertEquals(emptyMap<String, Boolean>(), broker.sessions())
    }

    @Test
    fun probe_unreachableBrokerInSettings_keepsTheAccountOnItsBrokerAndLeavesNoOtherSession() {
        assertNull(probe("alice-secret"))
        // A port where nothing listens: the probe gives up, the settings and the session return to the broker.
        val nowhere = BrokerAddress(EmbeddedBroker.HOST, BrokerProcess.freePort())
        val problem = runBlocking { chat.probe("alice", nowhere, "alice-secret") }

        assertEquals(true, problem!!.startsWith("No answer from $nowhere within 5 s."))
        assertEquals(address.toString(), chat.settings.preferences.value.brokerUrl)
        runBlocking { withTimeout(20_000) { chat.sync.connection.first { it == ConnectionState.Connected } } }
        assertEquals(mapOf(phoneSession() to true), broker.sessions())
    }

    /**
     * The honest tick: while alice's app is closed (no session; the broker keeps her persistent one and queues),
     * bob's message gets no delivered receipt, however long he waits: his phone shows one tick. When alice's app
     * runs again the queued message is stored, and only then does bob get "delivered" for it.
     */
    @Test
    fun closedReceiver_noDeliveredReceiptUntilTheMessageIsStored() = runBlocking {
        assertNull(probe("alice-secret"))
        // Closed: the account's session ends (a clean disconnect; the broker keeps the session and queues).
        chat.settings.update { it.copy(userName = null) }
        awaitTrue("alice's session kept but disconnected") { broker.sessions() == mapOf(phoneSession() to false) }
        val bobInbox = CopyOnWriteArrayList<InboxEvent>()
        val bob = sealingBob()
        bob.connect(InboxListener { bobInbox += it })
        val message = ChatMessage.compose("bob", "are you there?", null, HapticIcon.KNOCK, Clock.SYSTEM)
        // Sealed, as the app (end-to-end by default) accepts: alice's key stays retained while she is away.
        sendWhenKeyKnown(bob, "alice", message)

        delay(3_000)
        // (Capabilities arrive, retained; receipts do not.)
        assertEquals(emptyList<InboxEvent>(), bobInbox.filterIsInstance<InboxEvent.ReceiptReceived>())
        assertEquals(emptyList<String>(), chat.repository.messages("bob").first().map { it.text })

        // Open again: the queued message arrives, is stored, and bob hears "delivered" for exactly that message.
        chat.settings.update { it.copy(userName = "alice") }
        awaitTrue("bob's delivered receipt") { bobInbox.any { it is InboxEvent.ReceiptReceived } }
        val receipt = bobInbox.filterIsInstance<InboxEvent.ReceiptReceived>().first().receipt
        assertEquals(listOf(message.id, "alice", "DELIVERED"), listOf(receipt.messageId, receipt.from, receipt.state.name))
        assertEquals(listOf("are you there?"), chat.repository.messages("bob").first().map { it.text })
    }

    /**
     * bob's message arrives while no screen is open and is announced; the user answers in the
     * notification (the posted action's own PendingIntent, filled in as the system fills it) and bob
     * receives the reply through the broker.
     */
    @Test
    fun replyFromTheNotification_reachesThePeerThroughTheBroker() = runBlocking {
        assertNull(probe("alice-secret"))
        val bobInbox = CopyOnWriteArrayList<InboxEvent>()
        val bob = sealingBob()
        bob.connect(InboxListener { bobInbox += it })
        sendWhenKeyKnown(bob, "alice", ChatMessage.compose("bob", "are you coming?", null, HapticIcon.KNOCK, Clock.SYSTEM))

        awaitTrue("the notification") { shadowOf(notifications).getNotification("bob", MessageNotifier.NOTIFICATION_ID) != null }
        val posted = shadowOf(notifications).getNotification("bob", MessageNotifier.NOTIFICATION_ID)
        val reply = posted.actions.single { it.title.toString() == "Reply" }
        val typed = Intent()
        RemoteInput.addResultsToIntent(reply.remoteInputs, typed, Bundle().apply { putCharSequence(MessageNotifier.KEY_REPLY, "on my way") })
        reply.actionIntent.send(app, 0, typed)
        shadowOf(Looper.getMainLooper()).idle()
        awaitTrue("the reply stored") { chat.repository.messages("bob").first().any { it.outgoing } }

        awaitTrue("bob receives the reply") { bobInbox.any { it is InboxEvent.MessageReceived } }
        val received = bobInbox.filterIsInstance<InboxEvent.MessageReceived>().map { it.message }
        assertEquals(listOf("alice" to "on my way"), received.map { it.sender to it.text })
        // The answered notification is gone; the reply is the conversation's latest own message.
        awaitTrue("the notification cleared") { shadowOf(notifications).getNotification("bob", MessageNotifier.NOTIFICATION_ID) == null }
        val stored = chat.repository.messages("bob").first()
        assertEquals(listOf("are you coming?" to false, "on my way" to true), stored.map { it.text to it.outgoing })
    }

    /**
     * A replay after "Delete conversation": the operator recorded a genuine payload of bob's (sealed for alice and
     * signed by bob) and publishes it again, byte for byte, once alice has deleted the conversation. The receive path
     * (broker, the app's sealing messenger, ChatSync, Room) shows it once: the replay stores no row, brings no
     * conversation back, and the id stays seen; a fresh message of bob's after it is shown as usual.
     */
    @Test
    fun replayOfAGenuineSealedPayload_afterDeleteConversation_isNotShownAgain() = runBlocking {
        val bobKeys = EndToEnd(Identity.generate("bob"), TestKeyPins())
        val fast = RetryPolicy(initialDelayMillis = 50, maxDelayMillis = 500, jitter = 0.0)
        val bobPhone = MqttMessenger(MqttSettings(address, "bob", "bob-secret", DeviceId.generate(), reconnectPolicy = fast), bobKeys)
        bob = bobPhone
        bobPhone.connect(InboxListener { })
        assertNull(probe("alice-secret"))
        awaitTrue("bob's key pinned") { chat.peerKeys("bob") == PeerKeys.PUBLISHED }
        // bob's messenger learns alice's key from her retained one; the first message goes through it.
        val meet = ChatMessage.compose("bob", "meet at 5", null, HapticIcon.KNOCK, Clock.SYSTEM)
        sendWhenKeyKnown(bobPhone, "alice", meet)
        awaitTrue("bob's message stored") { chat.repository.messages("bob").first().isNotEmpty() }
        // What the operator recorded: bob's genuine bytes for that message, published again from bob's name.
        val recorded = bobKeys.seal("alice", MessageCodec.encode(meet))
        val wire = MqttClient.builder().useMqttVersion3().identifier("bob:" + DeviceId.generate().value)
            .serverHost(address.host).serverPort(address.port)
            .simpleAuth().username("bob").password("bob-secret".toByteArray()).applySimpleAuth()
            .buildAsync()
        wire.connect().get(20, TimeUnit.SECONDS)
        val after = ChatMessage.compose("bob", "after the replay", null, null, Clock.SYSTEM)
        try {
            chat.repository.deleteConversation("bob")
            assertEquals(emptyList<String>(), chat.repository.conversations().first().map { it.peer })

            wire.publishWith().topic(Topics.inbox("alice", "bob")).qos(MqttQos.AT_LEAST_ONCE).payload(recorded).send().get(20, TimeUnit.SECONDS)
            wire.publishWith().topic(Topics.inbox("alice", "bob")).qos(MqttQos.AT_LEAST_ONCE)
                .payload(bobKeys.seal("alice", MessageCodec.encode(after))).send().get(20, TimeUnit.SECONDS)
            awaitTrue("the message after the replay stored") { chat.repository.messages("bob").first().isNotEmpty() }
        } finally {
            wire.disconnect().get(20, TimeUnit.SECONDS)
        }
        // One inbox, in order: the replay arrived before the later message and was refused.
        assertEquals(listOf("after the replay"), chat.repository.messages("bob").first().map { it.text })
        assertEquals(listOf("bob"), chat.repository.conversations().first().map { it.peer })
        assertEquals(setOf(meet.id, after.id), seenIds("bob"))
    }

    /** The ids Room keeps as seen from [peer], read from the app's database file on a connection of its own. */
    private fun seenIds(peer: String): Set<String> =
        SQLiteDatabase.openDatabase(app.getDatabasePath(HapticonDatabase.NAME).path, null, SQLiteDatabase.OPEN_READONLY).use { db ->
            db.rawQuery("SELECT message_id FROM seen_messages WHERE peer = ?", arrayOf(peer)).use { c ->
                generateSequence { if (c.moveToNext()) c.getString(0) else null }.toSet()
            }
        }

    /**
     * End to end by default: the app's session publishes alice's key and pins bob's; a peer who never published a key
     * (carol) is named as such for "New chat", and with encryption switched off no key is needed.
     */
    @Test
    fun endToEndByDefault_peerWithKeysAndPeerWithout_areTold() = runBlocking {
        assertEquals(true, chat.settings.preferences.value.endToEnd)
        assertEquals(PeerKeys.NOT_KNOWN_YET, chat.peerKeys("bob")) // no account yet
        val bobInbox = CopyOnWriteArrayList<InboxEvent>()
        val bob = sealingBob()
        bob.connect(InboxListener { bobInbox += it })
        assertNull(probe("alice-secret"))
        awaitTrue("bob's key pinned") { chat.peerKeys("bob") == PeerKeys.PUBLISHED }
        assertEquals(PeerKeys.NONE_PUBLISHED, chat.peerKeys("carol"))
        // alice's key was published on connecting: bob can seal for her, and what he sends is stored.
        sendWhenKeyKnown(bob, "alice", ChatMessage.compose("bob", "sealed hello", null, null, Clock.SYSTEM))
        awaitTrue("bob's sealed message stored") { chat.repository.messages("bob").first().any { it.text == "sealed hello" } }
        chat.settings.update { it.copy(endToEnd = false) }
        assertEquals(PeerKeys.NOT_NEEDED, chat.peerKeys("carol"))
    }
}
