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
import org.hapticon.app.HapticonApplication
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
 * notification's receiver) against the embedded broker in a child JVM, with bob on another client.
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
     * bob's message arrives while no screen is open and is announced; the user answers in the
     * notification (the posted action's own PendingIntent, filled in as the system fills it) and bob
     * receives the reply through the broker.
     */
    @Test
    fun replyFromTheNotification_reachesThePeerThroughTheBroker() = runBlocking {
        assertNull(probe("alice-secret"))
        val bobInbox = CopyOnWriteArrayList<InboxEvent>()
        val fast = RetryPolicy(initialDelayMillis = 50, maxDelayMillis = 500, jitter = 0.0)
        val bob = MqttMessenger(MqttSettings(address, "bob", "bob-secret", DeviceId.generate(), reconnectPolicy = fast)).also { bob = it }
        bob.connect(InboxListener { bobInbox += it })
        bob.send("alice", ChatMessage.compose("bob", "are you coming?", null, HapticIcon.KNOCK, Clock.SYSTEM))

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
}
