package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.mqtt3.Mqtt3AsyncClient
import com.hivemq.client.mqtt.mqtt3.exceptions.Mqtt3ConnAckException
import com.hivemq.client.mqtt.mqtt3.message.connect.connack.Mqtt3ConnAckReturnCode
import kotlinx.coroutines.runBlocking
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.CollectingListener
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.RejectionReason
import org.hapticon.messaging.Topics
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import java.util.concurrent.ExecutionException
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

/**
 * What a third, authenticated user (mallory) can do to alice and bob, against a broker that runs the
 * shipped users/ACL model: read nothing of bob's, publish nothing as alice, take nothing of bob's session.
 * Run against the embedded broker ([EmbeddedBrokerSecurityTest]) and a real Mosquitto with the deployment
 * configuration ([MosquittoSecurityTest]).
 */
abstract class BrokerSecurityContract {
    protected abstract val alice: String
    protected abstract val bob: String
    protected abstract val mallory: String
    protected abstract val address: BrokerAddress

    /** [user]'s password on the broker. */
    protected abstract fun password(user: String): String

    /** True when the broker refuses a client id that is not the user name; Mosquitto replaces it instead. */
    protected abstract val refusesForeignClientIds: Boolean

    /** What the broker logged, for failure messages. */
    protected open fun brokerLog(): String = ""

    private val messengers = mutableListOf<MqttMessenger>()
    private val rawClients = mutableListOf<Mqtt3AsyncClient>()

    @After
    fun disconnectClients() {
        runBlocking { messengers.forEach { it.disconnect() } }
        rawClients.forEach { runCatching { it.disconnect().get(5, TimeUnit.SECONDS) } }
    }

    protected fun connected(user: String, listener: CollectingListener = CollectingListener()): MqttMessenger =
        MqttMessenger(MqttSettings(address, user, password(user), reconnectPolicy = FAST_RECONNECT))
            .also { messengers += it; runBlocking { it.connect(listener) } }

    /** A bare client as [user] (password [password]) with client id [clientId], connected (throws when refused). */
    protected fun raw(user: String?, clientId: String = user ?: "anonymous", password: String? = user?.let(::password)): Mqtt3AsyncClient {
        var builder = MqttClient.builder().useMqttVersion3().identifier(clientId).serverHost(address.host).serverPort(address.port)
        if (user != null) builder = builder.simpleAuth().username(user).password(password!!.toByteArray()).applySimpleAuth()
        val client = builder.buildAsync()
        rawClients += client
        try {
            client.connectWith().cleanSession(false).send().get(20, TimeUnit.SECONDS)
        } catch (e: ExecutionException) {
            throw e.cause!!
        }
        return client
    }

    private fun Mqtt3AsyncClient.publishQuietly(topic: String, payload: ByteArray, retain: Boolean = false) {
        // A broker may drop a denied publish (Mosquitto) or close the connection (HiveMQ with MQTT 3.1.1).
        runCatching { publishWith().topic(topic).qos(MqttQos.AT_LEAST_ONCE).retain(retain).payload(payload).send().get(10, TimeUnit.SECONDS) }
    }

    private fun returnCodeOf(connect: () -> Unit): Mqtt3ConnAckReturnCode? = try {
        connect()
        null
    } catch (e: Mqtt3ConnAckException) {
        e.mqttMessage.returnCode
    }

    @Test
    fun thirdUser_subscribingToEverythingAndBobsInbox_receivesNothingOfBobs() {
        val received = LinkedBlockingQueue<String>()
        val eavesdropper = raw(mallory)
        for (filter in listOf("#", "hapticon/#", Topics.inboxFilter(bob), "hapticon/v1/inbox/+/+", Topics.inboxFilter(mallory))) {
            // Each alone: the embedded broker refuses the wide ones in the SUBACK, Mosquitto 2.0 grants them and
            // filters what it delivers. Either way nothing of bob's may arrive.
            runCatching {
                eavesdropper.subscribeWith().topicFilter(filter).qos(MqttQos.AT_LEAST_ONCE)
                    .callback { received.put(it.topic.toString()) }.send().get(20, TimeUnit.SECONDS)
            }
        }
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        val aliceMessenger = connected(alice)
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

    @Test
    fun thirdUser_publishingAsAlice_isNeverShownAsAlice() {
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        val forger = raw(mallory)
        val forged = ChatMessage.compose(alice, "I am alice")
        // 1. Under mallory's own name with alice in the payload: the broker lets it through, bob drops it.
        forger.publishQuietly(Topics.inbox(bob, mallory), MessageCodec.encode(forged))
        // 2. Under alice's name: the broker's ACL refuses it.
        forger.publishQuietly(Topics.inbox(bob, alice), MessageCodec.encode(forged))
        val genuine = ChatMessage.compose(alice, "the real alice")
        runBlocking { connected(alice).send(bob, genuine) }
        val events = bobInbox.awaitEvents(2)
        val rejection = (events[0] as InboxEvent.Rejected).rejection
        assertEquals(RejectionReason.INVALID_VALUE to "sender", rejection.reason to rejection.field)
        assertEquals(InboxEvent.MessageReceived(genuine), events[1])
    }

    @Test
    fun thirdUser_retainingKeysUnderAlicesName_isRefused_ownKeysAreReadByAll() {
        // End-to-end keys are pinned on first contact: a key retained under alice's name by mallory must never be
        // seen. The permitted publish goes first: HiveMQ closes the connection on the denied one.
        val forger = raw(mallory)
        forger.publishQuietly(Topics.keys(mallory), "mallory's own key".toByteArray(), retain = true)
        forger.publishQuietly(Topics.keys(alice), "mallory's key for alice".toByteArray(), retain = true)
        val seen = LinkedBlockingQueue<String>()
        raw(bob).subscribeWith().topicFilter(Topics.ALL_KEYS).qos(MqttQos.AT_LEAST_ONCE)
            .callback { seen.put(it.topic.toString() + " " + String(it.payloadAsBytes)) }.send().get(20, TimeUnit.SECONDS)
        assertEquals("${Topics.keys(mallory)} mallory's own key", seen.poll(CollectingListener.WAIT_SECONDS, TimeUnit.SECONDS))
        Thread.sleep(300)
        assertEquals(emptyList<String>(), seen.filter { it.contains(alice) })
        // An empty retained message deletes mallory's: a retained payload left on the shared embedded broker
        // outlives this test and its restarts (see BrokerFixture).
        raw(mallory).publishQuietly(Topics.keys(mallory), ByteArray(0), retain = true)
    }

    private lateinit var aliceMessenger: MqttMessenger

    /** Bob's persistent session with [count] messages from alice (connected as [aliceMessenger]) queued in it; returns them. */
    private fun queueForOfflineBob(count: Int): List<ChatMessage> {
        connected(bob).let { runBlocking { it.disconnect() } }
        val queued = List(count) { ChatMessage.compose(alice, "queued $it") }
        aliceMessenger = connected(alice)
        runBlocking { queued.forEach { aliceMessenger.send(bob, it) } }
        return queued
    }

    @Test
    fun thirdUser_connectingWithBobsClientId_cannotTakeBobsSession() {
        val queued = queueForOfflineBob(2)
        val code = returnCodeOf { raw(mallory, clientId = bob).subscribeWith().topicFilter("#").send().get(10, TimeUnit.SECONDS) }
        if (refusesForeignClientIds) assertEquals(Mqtt3ConnAckReturnCode.IDENTIFIER_REJECTED, code) else assertEquals(null, code)
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        assertEquals(queued.map { InboxEvent.MessageReceived(it) }, bobInbox.awaitEvents(2))
    }

    /**
     * True when a refused CONNECT with bob's client id leaves bob's session alone. Mosquitto 2.0.11 does
     * not: after such a CONNECT bob's queued messages are gone and his next connection (SUBACK granted)
     * receives nothing either (observed here; the known part is eclipse-mosquitto/mosquitto#3551, open for
     * 2.1.2 too). docs/security.md lists it; the embedded broker is not affected.
     */
    protected abstract val keepsSessionsOnRefusedConnects: Boolean

    @Test
    fun strangerWithBobsClientId_noOrWrongPassword_isRefused() {
        val queued = queueForOfflineBob(2)
        assertEquals(Mqtt3ConnAckReturnCode.NOT_AUTHORIZED, returnCodeOf { raw(null, clientId = bob) })
        assertTrue(returnCodeOf { raw(bob, password = "guess") } in setOf(Mqtt3ConnAckReturnCode.NOT_AUTHORIZED, Mqtt3ConnAckReturnCode.BAD_USER_NAME_OR_PASSWORD))
        if (!keepsSessionsOnRefusedConnects) return
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        assertEquals(queued.map { InboxEvent.MessageReceived(it) }, bobInbox.awaitEvents(2))
    }

    @Test
    fun anonymousClient_isRefused() {
        val code = returnCodeOf { raw(null) }
        if (code != Mqtt3ConnAckReturnCode.NOT_AUTHORIZED) fail("an anonymous CONNECT got $code")
    }
}
