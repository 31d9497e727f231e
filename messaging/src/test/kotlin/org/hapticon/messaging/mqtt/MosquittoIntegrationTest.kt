package org.hapticon.messaging.mqtt

import org.hapticon.testing.InMemoryOutbox
import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.mqtt3.Mqtt3BlockingClient
import com.hivemq.client.mqtt.mqtt3.message.subscribe.suback.Mqtt3SubAckReturnCode
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.BoundedDeduplicator
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.CollectingListener
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.OutboxSender
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.Topics
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.util.Collections
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

/** The messenger against a real Mosquitto running the shipped deployment configuration and ACL. */
class MosquittoIntegrationTest {
    @get:Rule
    val temp = TemporaryFolder()

    private lateinit var mosquitto: MosquittoProcess
    private val messengers = mutableListOf<MqttMessenger>()
    private val rawClients = mutableListOf<Mqtt3BlockingClient>()

    @Before
    fun startMosquitto() {
        MosquittoProcess.assumeInstalled()
        mosquitto = MosquittoProcess(temp.root, PASSWORDS)
        mosquitto.start()
    }

    @After
    fun stopMosquitto() {
        runBlocking { messengers.forEach { it.disconnect() } }
        rawClients.forEach { runCatching { it.disconnect() } }
        if (::mosquitto.isInitialized) mosquitto.stop()
    }

    private fun messenger(user: String, password: String = PASSWORDS.getValue(user)) =
        MqttMessenger(MqttSettings(mosquitto.address, user, password, TestDevices.of(user), reconnectPolicy = FAST_RECONNECT)).also { messengers += it }

    private fun connected(user: String, listener: CollectingListener) =
        messenger(user).also { runBlocking { it.connect(listener) } }

    @Test
    fun messageWithIcon_receiptsAndCapabilities_flowBetweenTwoUsers() = runBlocking {
        val aliceInbox = CollectingListener()
        val alice = connected("alice", aliceInbox)
        val bobInbox = CollectingListener()
        val bob = connected("bob", bobInbox)
        val capabilities = Capabilities("bob", RendererKind.AMPLITUDE_WAVEFORM, amplitudeControl = true, apiLevel = 34)
        bob.publishCapabilities(capabilities)
        assertEquals(InboxEvent.CapabilitiesReceived(capabilities), aliceInbox.awaitEvent())
        assertEquals(InboxEvent.CapabilitiesReceived(capabilities), bobInbox.awaitEvent())

        val message = ChatMessage.compose("alice", "knock knock", icon = HapticIcon.KNOCK)
        alice.send("bob", message)
        assertEquals(InboxEvent.MessageReceived(message), bobInbox.awaitEvent())
        val delivered = Receipt(message.id, "bob", ReceiptState.DELIVERED, message.sentAtMillis + 5)
        bob.send("alice", delivered)
        assertEquals(InboxEvent.ReceiptReceived(delivered), aliceInbox.awaitEvent())
    }

    @Test
    fun thousandMessages_mosquittoSigkilledMidStreamWhileTheReceiverIsOffline_noneLostNoneShownTwice() {
        val scenario = EndToEndScenario("alice", "bob") { user, listener ->
            messenger(user).also { runBlocking { it.connect(listener) } }
        }
        scenario.run(1_000) {
            mosquitto.kill()
            mosquitto.start()
        }
        println("end-to-end delivery, Mosquitto SIGKILLed: 1000 shown once, ${scenario.deliveries.get() - 1000} repeats dropped")
    }

    @Test
    fun acl_forgedCapabilities_areDroppedWhileInboxWritesPass() {
        val bobInbox = CollectingListener()
        connected("bob", bobInbox)
        val mallory = rawClient("mallory")
        val forged = Capabilities("alice", RendererKind.NONE, amplitudeControl = false)
        mallory.publishQos1(Topics.capabilities("alice"), MessageCodec.encode(forged), retain = true)
        val marker = ChatMessage.compose("mallory", "after the forgery")
        mallory.publishQos1(Topics.inbox("bob", "mallory"), MessageCodec.encode(marker))
        // Mosquitto keeps one publisher's messages in order: had the forgery passed, it would come first.
        assertEquals(InboxEvent.MessageReceived(marker), bobInbox.awaitEvent())
    }

    @Test
    fun ping_mosquittoAnswersTheKeepAliveRoundTrip_andTheInboxStaysSubscribed() = runBlocking {
        val alice = connected("alice", CollectingListener())
        val bobInbox = CollectingListener()
        val bob = connected("bob", bobInbox)
        // Whatever Mosquitto checks for an UNSUBSCRIBE, the filter is one the ACL lets bob read.
        assertEquals(true, bob.ping(5_000))
        val message = ChatMessage.compose("alice", "still there?")
        alice.send("bob", message)
        assertEquals(InboxEvent.MessageReceived(message), bobInbox.awaitEvent())
    }

    @Test
    fun wrongPassword_connectFailsForGood() {
        val impostor = messenger("alice", password = "guess")
        val e = assertThrows(MessagingException::class.java) { runBlocking { impostor.connect(CollectingListener()) } }
        assertEquals("cannot connect to ${mosquitto.address} as alice: not authorized", e.message)
    }

    /** A bare client with [user]'s credentials that can attempt anything. */
    private fun rawClient(user: String): Mqtt3BlockingClient {
        val client = MqttClient.builder().useMqttVersion3().identifier(user)
            .serverHost(MosquittoProcess.HOST).serverPort(mosquitto.port)
            .simpleAuth().username(user).password(PASSWORDS.getValue(user).toByteArray()).applySimpleAuth()
            .buildBlocking()
        client.connect()
        rawClients += client
        return client
    }

    private companion object {
        val PASSWORDS = mapOf("alice" to "alice-secret", "bob" to "bob-secret", "mallory" to "mallory-secret")
    }
}
