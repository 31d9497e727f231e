package org.hapticon.messaging.mqtt

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
import org.hapticon.messaging.BoundedDeduplicator
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.CollectingListener
import org.hapticon.messaging.InMemoryOutbox
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.OutboxSender
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.RendererKind
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

    private fun messenger(user: String, device: String = "test", password: String = PASSWORDS.getValue(user)) =
        MqttMessenger(MqttSettings(mosquitto.address, user, device, password, reconnectPolicy = FAST_RECONNECT)).also { messengers += it }

    private fun connected(user: String, listener: CollectingListener, device: String = "test") =
        messenger(user, device).also { runBlocking { it.connect(listener) } }

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
    fun mosquittoRestartMidStream_offlineRecipientGetsEveryMessageExactlyOnce() = runBlocking {
        val count = 200
        val bob = connected("bob", CollectingListener(), device = "phone")
        bob.disconnect() // offline from here: Mosquitto queues for its session
        val alice = connected("alice", CollectingListener(), device = "laptop")
        val outbox = InMemoryOutbox()
        val sender = OutboxSender(outbox, alice, RetryPolicy(initialDelayMillis = 50, maxDelayMillis = 500), Clock.SYSTEM, sendTimeoutMillis = 2_000)
        val messages = List(count) { ChatMessage.compose("alice", "message $it") }
        messages.forEach { outbox.enqueue("bob", it) }
        val sending = launch(Dispatchers.Default) { sender.run() }
        withTimeout(60_000) {
            while (outbox.pending().size > count / 2) delay(1)
            mosquitto.restart()
            while (outbox.pending().isNotEmpty()) delay(10)
        }
        sending.cancelAndJoin()

        val deduplicator = BoundedDeduplicator()
        val accepted = Collections.synchronizedList(mutableListOf<String>())
        val bobAgain = messenger("bob", device = "phone")
        bobAgain.connect { event ->
            if (event is InboxEvent.MessageReceived && deduplicator.firstSeen(event.message.id)) accepted += event.message.id
        }
        withTimeout(60_000) { while (accepted.size < count) delay(10) }
        assertEquals(messages.map { it.id }.toSet(), accepted.toSet())
        assertEquals(count, accepted.size)
    }

    @Test
    fun acl_anotherUsersInbox_neverReachesAnEavesdropper() = runBlocking {
        val received = LinkedBlockingQueue<String>()
        val mallory = rawClient("mallory")
        // Mosquitto 2.0 grants the subscription and filters what it delivers; later versions refuse it in the
        // SUBACK. Either way nothing of alice's may arrive.
        val subAck = mallory.toAsync().subscribeWith()
            .addSubscription().topicFilter(Topics.inbox("mallory")).qos(MqttQos.AT_LEAST_ONCE).applySubscription()
            .addSubscription().topicFilter(Topics.inbox("alice")).qos(MqttQos.AT_LEAST_ONCE).applySubscription()
            .callback { received.put(it.topic.toString()) }
            .send().get(20, TimeUnit.SECONDS)
        assertEquals(Mqtt3SubAckReturnCode.SUCCESS_MAXIMUM_QOS_1, subAck.returnCodes[0])
        val aliceInbox = CollectingListener()
        connected("alice", aliceInbox)
        val bob = connected("bob", CollectingListener())
        val secret = ChatMessage.compose("bob", "for alice only")
        bob.send("alice", secret)
        bob.send("mallory", ChatMessage.compose("bob", "for mallory"))
        // One publisher's messages arrive in order: had alice's reached mallory, it would come first.
        assertEquals(Topics.inbox("mallory"), received.poll(CollectingListener.WAIT_SECONDS, TimeUnit.SECONDS))
        assertEquals(InboxEvent.MessageReceived(secret), aliceInbox.awaitEvent())
    }

    @Test
    fun acl_forgedCapabilities_areDroppedWhileInboxWritesPass() {
        val bobInbox = CollectingListener()
        connected("bob", bobInbox)
        val mallory = rawClient("mallory")
        val forged = Capabilities("alice", RendererKind.NONE, amplitudeControl = false)
        mallory.publishQos1(Topics.capabilities("alice"), MessageCodec.encode(forged), retain = true)
        val marker = ChatMessage.compose("mallory", "after the forgery")
        mallory.publishQos1(Topics.inbox("bob"), MessageCodec.encode(marker))
        // Mosquitto keeps one publisher's messages in order: had the forgery passed, it would come first.
        assertEquals(InboxEvent.MessageReceived(marker), bobInbox.awaitEvent())
    }

    @Test
    fun wrongPassword_connectFailsForGood() {
        val impostor = messenger("alice", password = "guess")
        val e = assertThrows(MessagingException::class.java) { runBlocking { impostor.connect(CollectingListener()) } }
        assertEquals("cannot connect to ${mosquitto.address} as alice: not authorized", e.message)
    }

    /** A bare client with [user]'s credentials that can attempt anything. */
    private fun rawClient(user: String): Mqtt3BlockingClient {
        val client = MqttClient.builder().useMqttVersion3().identifier("$user-raw")
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
