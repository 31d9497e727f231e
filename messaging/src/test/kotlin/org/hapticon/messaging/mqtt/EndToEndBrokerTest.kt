package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.mqtt3.Mqtt3BlockingClient
import kotlinx.coroutines.runBlocking
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.CollectingListener
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.RejectionReason
import org.hapticon.messaging.Topics
import org.hapticon.messaging.broker.AclFile
import org.hapticon.messaging.broker.BrokerSecurity
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.broker.PasswordFile
import org.hapticon.messaging.e2e.EndToEnd
import org.hapticon.messaging.e2e.Identity
import org.hapticon.testing.TestKeyPins
import org.junit.AfterClass
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import java.io.File
import java.nio.file.Files
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

/**
 * End-to-end protection against the one adversary authentication and ACLs cannot stop: the broker's
 * operator. The embedded broker runs the shipped ACL plus a user `operator` who may read and write every
 * topic (what whoever runs the broker can do anyway).
 */
class EndToEndBrokerTest {
    private val messengers = mutableListOf<MqttMessenger>()
    private val rawClients = mutableListOf<Mqtt3BlockingClient>()
    private val alice = uniqueUser("alice")
    private val bob = uniqueUser("bob")

    @After
    fun disconnect() {
        runBlocking { messengers.forEach { it.disconnect() } }
        rawClients.forEach { runCatching { it.disconnect() } }
    }

    private fun connected(user: String, e2e: EndToEnd?, listener: CollectingListener = CollectingListener()): MqttMessenger =
        MqttMessenger(MqttSettings(BrokerAddress(EmbeddedBroker.HOST, broker.port), user, register(user), TestDevices.of(user), reconnectPolicy = FAST_RECONNECT), e2e)
            .also { messengers += it; runBlocking { it.connect(listener) } }

    private fun operator(): Mqtt3BlockingClient =
        MqttClient.builder().useMqttVersion3().identifier(TestDevices.clientId("operator")).serverHost(EmbeddedBroker.HOST).serverPort(broker.port)
            .simpleAuth().username("operator").password(register("operator").toByteArray()).applySimpleAuth()
            .buildBlocking().also { it.connect(); rawClients += it }

    private fun e2e(user: String) = EndToEnd(Identity.generate(user), TestKeyPins())

    /** Waits until [e2e] has pinned [peer]'s key (its retained key message arrived). */
    private fun awaitKey(e2e: EndToEnd, peer: String) {
        val deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(CollectingListener.WAIT_SECONDS)
        while (e2e.safetyNumber(peer) == null) {
            if (System.nanoTime() > deadline) fail("no key of $peer arrived")
            Thread.sleep(5)
        }
    }

    @Test
    fun operatorSubscribedToEverything_seesOnlyCiphertext_andBobReadsTheMessage() {
        val seen = LinkedBlockingQueue<Pair<String, ByteArray>>()
        val op = operator()
        op.toAsync().subscribeWith().topicFilter("hapticon/v1/inbox/#").qos(MqttQos.AT_LEAST_ONCE)
            .callback { seen.put(it.topic.toString() to it.payloadAsBytes) }.send().get(20, TimeUnit.SECONDS)
        val bobE2e = e2e(bob)
        val bobInbox = CollectingListener()
        connected(bob, bobE2e, bobInbox)
        val aliceE2e = e2e(alice)
        val aliceInbox = CollectingListener()
        val aliceMessenger = connected(alice, aliceE2e, aliceInbox)
        awaitKey(aliceE2e, bob)
        val secret = ChatMessage.compose(alice, "the secret plan", sticker = "hug", icon = HapticIcon.KNOCK)
        runBlocking { aliceMessenger.send(bob, secret) }
        assertEquals(InboxEvent.MessageReceived(secret), bobInbox.awaitEvent())
        val (topic, payload) = seen.poll(CollectingListener.WAIT_SECONDS, TimeUnit.SECONDS)!!
        assertEquals(Topics.inbox(bob, alice), topic)
        val wire = String(payload, Charsets.ISO_8859_1)
        assertTrue(wire, wire.startsWith("{\"schema\":\"hapticon.sealed\",\"version\":1,\"keys\":\""))
        // Only base64 follows: no space, quote or '-' of the clear text (a short word like "hug" could occur by chance).
        for (clear in listOf("secret plan", secret.id, "\"sender\"", "\"sticker\"", "\"icon\"")) assertFalse("$clear readable on the broker", wire.contains(clear))
        // The receipt back is sealed for alice, and alice has pinned bob's key from it or from the key topic.
        val receipt = Receipt(secret.id, bob, ReceiptState.DELIVERED, 1L)
        runBlocking { messengers.first { it.user == bob }.send(alice, receipt) }
        assertEquals(InboxEvent.ReceiptReceived(receipt), aliceInbox.awaitEvent())
        val (receiptTopic, receiptPayload) = seen.poll(CollectingListener.WAIT_SECONDS, TimeUnit.SECONDS)!!
        assertEquals(Topics.inbox(alice, bob), receiptTopic)
        assertFalse(String(receiptPayload, Charsets.ISO_8859_1).contains(secret.id))
        assertEquals(aliceE2e.safetyNumber(bob), bobE2e.safetyNumber(alice))
    }

    @Test
    fun operatorForgingAsAlice_isRefusedEveryWay_andTheGenuineMessageStillArrives() {
        val bobE2e = e2e(bob)
        val bobInbox = CollectingListener()
        connected(bob, bobE2e, bobInbox)
        val aliceE2e = e2e(alice)
        val aliceMessenger = connected(alice, aliceE2e)
        awaitKey(aliceE2e, bob)
        awaitKey(bobE2e, alice) // first contact through alice's retained key
        val op = operator()
        val onAlicesTopic = Topics.inbox(bob, alice)
        // 1. Plaintext with alice's name: what an old client or the operator without keys can write.
        op.publishQos1(onAlicesTopic, MessageCodec.encode(ChatMessage.compose(alice, "plain forgery")))
        // 2. Sealed with keys the operator made and named alice: not the pinned ones.
        val fakeAlice = EndToEnd(Identity.generate(alice), TestKeyPins().apply { pin(bobE2e.identity.bundle) })
        op.publishQos1(onAlicesTopic, fakeAlice.seal(bob, MessageCodec.encode(ChatMessage.compose(alice, "sealed forgery"))))
        // 3. A genuine sealed payload of alice's, altered by one byte of ciphertext.
        val genuine = aliceE2e.seal(bob, MessageCodec.encode(ChatMessage.compose(alice, "altered")))
        val at = String(genuine, Charsets.ISO_8859_1).indexOf("\"ct\":\"") + 10
        op.publishQos1(onAlicesTopic, genuine.copyOf().also { it[at] = if (it[at] == 'A'.code.toByte()) 'B'.code.toByte() else 'A'.code.toByte() })
        // 4. The operator overwrites alice's retained key with its own.
        op.publishQos1(Topics.keys(alice), fakeAlice.identity.bundle.encoded, retain = true)
        val real = ChatMessage.compose(alice, "the real alice")
        runBlocking { aliceMessenger.send(bob, real) }
        val events = bobInbox.awaitEvents(5)
        val reasons = events.filterIsInstance<InboxEvent.Rejected>().map { it.rejection.reason }
        assertEquals(
            listOf(RejectionReason.NOT_ENCRYPTED, RejectionReason.KEY_CHANGED, RejectionReason.FORGED, RejectionReason.KEY_CHANGED),
            reasons,
        )
        assertEquals(InboxEvent.MessageReceived(real), events.last())
        val keyWarning = (events[3] as InboxEvent.Rejected).rejection.detail
        assertTrue(keyWarning, keyWarning.startsWith("$alice's key changed (safety number now "))
        // bob still pins alice's real key: both see the same safety number.
        assertEquals(bobE2e.safetyNumber(alice), aliceE2e.safetyNumber(bob))
    }

    @Test
    fun plaintextClients_getClearMessagesBothWays() {
        val carol = uniqueUser("carol")
        val carolInbox = CollectingListener()
        val carolMessenger = connected(carol, null, carolInbox) // an old client: no keys, no key topic
        val bobE2e = e2e(bob)
        val bobInbox = CollectingListener()
        val bobMessenger = connected(bob, bobE2e, bobInbox)
        // bob cannot seal for carol: she never published a key. The outbox keeps the message and says why.
        try {
            runBlocking { bobMessenger.send(carol, ChatMessage.compose(bob, "hi carol")) }
            fail("sent to a client without keys")
        } catch (e: MessagingException) {
            assertEquals("not sent: no key of $carol yet: $carol has not published one (an old client, or never connected with end-to-end encryption)", e.message)
        }
        // carol's plaintext to bob is refused by bob, with a reason.
        runBlocking { carolMessenger.send(bob, ChatMessage.compose(carol, "hi bob")) }
        val refused = (bobInbox.awaitEvent() as InboxEvent.Rejected).rejection
        assertEquals(RejectionReason.NOT_ENCRYPTED, refused.reason)
        assertEquals("unencrypted payload from $carol refused: this client requires end-to-end encryption ($carol's client is old or runs without it)", refused.detail)
        // A sealed payload reaching carol (the operator replays one) is named, not called garbage.
        val aliceE2e = EndToEnd(Identity.generate(alice), TestKeyPins().apply { pin(Identity.generate(carol).bundle) })
        operator().publishQos1(Topics.inbox(carol, alice), aliceE2e.seal(carol, "x".toByteArray()))
        val named = (carolInbox.awaitEvent() as InboxEvent.Rejected).rejection
        assertEquals(RejectionReason.ENCRYPTED to "end-to-end encrypted payload from $alice: this client has no keys to open it (turn end-to-end encryption on)", named.reason to named.detail)
    }

    companion object {
        private val root: File by lazy { Files.createTempDirectory("hapticon-e2e-broker").toFile() }
        private val passwords: PasswordFile by lazy { PasswordFile(File(root, "passwd")) }
        private val registered = mutableSetOf<String>()

        private val broker: EmbeddedBroker by lazy {
            // The operator's own rule: whoever runs the broker reads and writes everything.
            val acl = File(root, "aclfile").apply { writeText(AclFile.DEFAULT_TEXT + "user operator\ntopic readwrite #\n") }
            // Not alongside the shared broker: see OneBrokerAtATime.
            EmbeddedBroker(File(root, "store"), security = BrokerSecurity.Authenticated(passwords.file, acl)).also { OneBrokerAtATime.start(it) }
        }

        @Synchronized
        private fun register(user: String): String {
            if (registered.add(user)) passwords.add(user, "$user-secret".toCharArray(), iterations = 1_000)
            return "$user-secret"
        }

        @JvmStatic
        @AfterClass
        fun stopBroker() {
            broker.stop()
            root.deleteRecursively()
        }
    }
}
