package org.hapticon.messaging.mqtt

import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.mqtt3.Mqtt3AsyncClient
import com.hivemq.client.mqtt.mqtt3.Mqtt3ClientBuilder
import com.hivemq.client.mqtt.mqtt3.exceptions.Mqtt3ConnAckException
import com.hivemq.client.mqtt.mqtt3.message.connect.connack.Mqtt3ConnAckReturnCode
import kotlinx.coroutines.runBlocking
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.CollectingListener
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.RejectionReason
import org.hapticon.messaging.Topics
import org.junit.Assert.assertEquals
import java.util.concurrent.ExecutionException
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

/**
 * The broker clients one test opens: messengers, and bare HiveMQ clients for what the messenger never does
 * (a foreign client id, a forged topic). [close] disconnects them all, so a broker shared between tests is
 * left without this test's sessions.
 */
class TestClients {
    private val messengers = mutableListOf<MqttMessenger>()
    private val rawClients = mutableListOf<Mqtt3AsyncClient>()

    /** A messenger with [settings], connected and delivering to [listener]. */
    fun messenger(settings: MqttSettings, listener: InboxListener): MqttMessenger =
        MqttMessenger(settings).also { messengers += it; runBlocking { it.connect(listener) } }

    /** [builder]'s client, connected with a persistent session (clean session off); throws why the broker refused. */
    fun raw(builder: Mqtt3ClientBuilder): Mqtt3AsyncClient {
        val client = builder.buildAsync()
        rawClients += client
        try {
            client.connectWith().cleanSession(false).send().get(20, TimeUnit.SECONDS)
        } catch (e: ExecutionException) {
            throw e.cause!!
        }
        return client
    }

    /** Disconnects every client opened here. */
    fun close() {
        runBlocking { messengers.forEach { it.disconnect() } }
        rawClients.forEach { runCatching { it.disconnect().get(5, TimeUnit.SECONDS) } }
    }

    companion object {
        /** The CONNACK return code that refused [connect], or null when it connected. */
        fun returnCodeOf(connect: () -> Unit): Mqtt3ConnAckReturnCode? = try {
            connect()
            null
        } catch (e: Mqtt3ConnAckException) {
            e.mqttMessage.returnCode
        }
    }
}

/**
 * What a third, authenticated user (mallory) tries against alice and bob, and what the broker must make of it:
 * read nothing of bob's, be shown as nobody but mallory, take nothing of bob's session. The same whether users
 * log in with a password ([BrokerSecurityContract]) or a client certificate ([ClientCertificateContract]); only
 * how a client connects differs, and that is what the parameters say.
 */
class ThirdUserAttacks(
    private val alice: String,
    private val bob: String,
    private val mallory: String,
    /** A messenger connected as [user], delivering to [listener]. */
    private val connected: (user: String, listener: CollectingListener) -> MqttMessenger,
    /** A bare client authenticated as mallory, with client id [clientId], connected (throws when refused). */
    private val malloryWithClientId: (clientId: String) -> Mqtt3AsyncClient,
    /** True when the broker refuses a client id that is not one of the user's devices' (the embedded broker); Mosquitto cannot tell. */
    private val refusesForeignClientIds: Boolean,
) {
    /**
     * Mallory subscribes to each of [filters] (each alone: the embedded broker refuses the wide ones in the
     * SUBACK, Mosquitto 2.0 grants them and filters what it delivers); alice then writes to bob and to mallory.
     * Bob gets his, mallory gets exactly hers first, and nothing of bob's ever reaches mallory.
     */
    fun eavesdropping_receivesNothingOfBobs(filters: List<String>) {
        val received = LinkedBlockingQueue<String>()
        val eavesdropper = malloryWithClientId(TestDevices.clientId(mallory))
        for (filter in filters) {
            runCatching {
                eavesdropper.subscribeWith().topicFilter(filter).qos(MqttQos.AT_LEAST_ONCE)
                    .callback { received.put(it.topic.toString()) }.send().get(20, TimeUnit.SECONDS)
            }
        }
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        val aliceMessenger = connected(alice, CollectingListener())
        val secret = ChatMessage.compose(alice, "for bob only")
        runBlocking {
            aliceMessenger.send(bob, secret)
            aliceMessenger.send(mallory, ChatMessage.compose(alice, "for mallory"))
        }
        assertEquals(InboxEvent.MessageReceived(secret), bobInbox.awaitEvent())
        // One publisher's messages arrive in order: had bob's reached mallory, it would come first.
        assertEquals(Topics.inbox(mallory, alice), received.poll(CollectingListener.WAIT_SECONDS, TimeUnit.SECONDS))
        Thread.sleep(300) // a duplicate through a granted "#" may follow; nothing of bob's may
        assertEquals(emptyList<String>(), received.filter { it.contains("/$bob") })
    }

    /**
     * Mallory forges a message from alice twice: under mallory's own name with alice in the payload (the broker
     * lets it through, bob's inbox rejects the sender), and under alice's name (the broker's ACL refuses it).
     * Bob's next event after the rejection is the genuine alice's message.
     */
    fun forgingAlice_isNeverShownAsAlice() {
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        val forger = malloryWithClientId(TestDevices.clientId(mallory))
        val forged = ChatMessage.compose(alice, "I am alice")
        for (topic in listOf(Topics.inbox(bob, mallory), Topics.inbox(bob, alice))) {
            publishQuietly(forger, topic, MessageCodec.encode(forged))
        }
        val genuine = ChatMessage.compose(alice, "the real alice")
        runBlocking { connected(alice, CollectingListener()).send(bob, genuine) }
        val events = bobInbox.awaitEvents(2)
        val rejection = (events[0] as InboxEvent.Rejected).rejection
        assertEquals(RejectionReason.INVALID_VALUE to "sender", rejection.reason to rejection.field)
        assertEquals(InboxEvent.MessageReceived(genuine), events[1])
    }

    /**
     * Mallory connects with the client ids of bob's she can know or make up (bob's user name; `bob:` and a device id
     * of her own) while bob is offline with two messages queued: refused ([refusesForeignClientIds]) or given a
     * session of her own, and either way bob later receives both. Bob's own client id holds a secret she cannot present.
     */
    fun bobsClientId_cannotTakeBobsSession() {
        val queued = queueForOfflineBob(2)
        for (clientId in listOf(bob, "$bob:${DeviceId.generate().value}")) {
            val code = TestClients.returnCodeOf { malloryWithClientId(clientId).subscribeWith().topicFilter("#").send().get(10, TimeUnit.SECONDS) }
            assertEquals(clientId, if (refusesForeignClientIds) Mqtt3ConnAckReturnCode.IDENTIFIER_REJECTED else null, code)
        }
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        assertEquals(queued.map { InboxEvent.MessageReceived(it) }, bobInbox.awaitEvents(2))
    }

    /** Bob's persistent session with [count] messages from alice queued in it while he is offline; returns them. */
    fun queueForOfflineBob(count: Int): List<ChatMessage> {
        connected(bob, CollectingListener()).let { runBlocking { it.disconnect() } }
        val queued = List(count) { ChatMessage.compose(alice, "queued $it") }
        val aliceMessenger = connected(alice, CollectingListener())
        // Acknowledged by the broker, so queued; alice leaves, so that the test can connect her device again.
        runBlocking {
            queued.forEach { aliceMessenger.send(bob, it) }
            aliceMessenger.disconnect()
        }
        return queued
    }

    companion object {
        /** Publishes where the broker may refuse it: Mosquitto drops a denied publish, HiveMQ (MQTT 3.1.1) closes the connection. */
        fun publishQuietly(client: Mqtt3AsyncClient, topic: String, payload: ByteArray, retain: Boolean = false) {
            runCatching { client.publishWith().topic(topic).qos(MqttQos.AT_LEAST_ONCE).retain(retain).payload(payload).send().get(10, TimeUnit.SECONDS) }
        }
    }
}
