package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.mqtt3.Mqtt3AsyncClient
import com.hivemq.client.mqtt.mqtt3.message.connect.connack.Mqtt3ConnAckReturnCode
import org.hapticon.messaging.CollectingListener
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.Topics
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
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

    private val clients = TestClients()

    @After
    fun disconnectClients() = clients.close()

    protected fun connected(user: String, listener: CollectingListener = CollectingListener()): MqttMessenger =
        clients.messenger(MqttSettings(address, user, password(user), reconnectPolicy = FAST_RECONNECT), listener)

    /** A bare client as [user] (password [password]) with client id [clientId], connected (throws when refused). */
    protected fun raw(user: String?, clientId: String = user ?: "anonymous", password: String? = user?.let(::password)): Mqtt3AsyncClient {
        var builder = MqttClient.builder().useMqttVersion3().identifier(clientId).serverHost(address.host).serverPort(address.port)
        if (user != null) builder = builder.simpleAuth().username(user).password(password!!.toByteArray()).applySimpleAuth()
        return clients.raw(builder)
    }

    private val attacks by lazy {
        ThirdUserAttacks(alice, bob, mallory, ::connected, { clientId -> raw(mallory, clientId = clientId) }, refusesForeignClientIds)
    }

    @Test
    fun thirdUser_subscribingToEverythingAndBobsInbox_receivesNothingOfBobs() =
        attacks.eavesdropping_receivesNothingOfBobs(listOf("#", "hapticon/#", Topics.inboxFilter(bob), "hapticon/v1/inbox/+/+", Topics.inboxFilter(mallory)))

    @Test
    fun thirdUser_publishingAsAlice_isNeverShownAsAlice() = attacks.forgingAlice_isNeverShownAsAlice()

    @Test
    fun thirdUser_retainingKeysUnderAlicesName_isRefused_ownKeysAreReadByAll() {
        // End-to-end keys are pinned on first contact: a key retained under alice's name by mallory must never be
        // seen. The permitted publish goes first: HiveMQ closes the connection on the denied one.
        val forger = raw(mallory)
        ThirdUserAttacks.publishQuietly(forger, Topics.keys(mallory), "mallory's own key".toByteArray(), retain = true)
        ThirdUserAttacks.publishQuietly(forger, Topics.keys(alice), "mallory's key for alice".toByteArray(), retain = true)
        val seen = LinkedBlockingQueue<String>()
        raw(bob).subscribeWith().topicFilter(Topics.ALL_KEYS).qos(MqttQos.AT_LEAST_ONCE)
            .callback { seen.put(it.topic.toString() + " " + String(it.payloadAsBytes)) }.send().get(20, TimeUnit.SECONDS)
        assertEquals("${Topics.keys(mallory)} mallory's own key", seen.poll(CollectingListener.WAIT_SECONDS, TimeUnit.SECONDS))
        Thread.sleep(300)
        assertEquals(emptyList<String>(), seen.filter { it.contains(alice) })
        // An empty retained message deletes mallory's: a retained payload left on the shared embedded broker
        // outlives this test and its restarts (see BrokerFixture).
        ThirdUserAttacks.publishQuietly(raw(mallory), Topics.keys(mallory), ByteArray(0), retain = true)
    }

    @Test
    fun thirdUser_connectingWithBobsClientId_cannotTakeBobsSession() = attacks.bobsClientId_cannotTakeBobsSession()

    /**
     * True when a refused CONNECT with bob's client id leaves bob's session alone. Mosquitto 2.0.11 does
     * not: after such a CONNECT bob's queued messages are gone and his next connection (SUBACK granted)
     * receives nothing either (observed here; the known part is eclipse-mosquitto/mosquitto#3551, open for
     * 2.1.2 too). docs/security.md lists it; the embedded broker is not affected.
     */
    protected abstract val keepsSessionsOnRefusedConnects: Boolean

    @Test
    fun strangerWithBobsClientId_noOrWrongPassword_isRefused() {
        val queued = attacks.queueForOfflineBob(2)
        assertEquals(Mqtt3ConnAckReturnCode.NOT_AUTHORIZED, TestClients.returnCodeOf { raw(null, clientId = bob) })
        assertTrue(TestClients.returnCodeOf { raw(bob, password = "guess") } in setOf(Mqtt3ConnAckReturnCode.NOT_AUTHORIZED, Mqtt3ConnAckReturnCode.BAD_USER_NAME_OR_PASSWORD))
        if (!keepsSessionsOnRefusedConnects) return
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        assertEquals(queued.map { InboxEvent.MessageReceived(it) }, bobInbox.awaitEvents(2))
    }

    @Test
    fun anonymousClient_isRefused() {
        val code = TestClients.returnCodeOf { raw(null) }
        if (code != Mqtt3ConnAckReturnCode.NOT_AUTHORIZED) fail("an anonymous CONNECT got $code")
    }
}
