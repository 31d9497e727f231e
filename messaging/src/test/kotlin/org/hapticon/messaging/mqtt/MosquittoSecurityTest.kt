package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import com.hivemq.client.mqtt.mqtt3.message.connect.connack.Mqtt3ConnAckReturnCode
import kotlinx.coroutines.runBlocking
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.CollectingListener
import org.hapticon.messaging.InboxEvent
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Test
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import org.junit.Before
import org.junit.Rule
import org.junit.rules.TemporaryFolder

/** [BrokerSecurityContract] against a real Mosquitto running companion/mosquitto's configuration and ACL. */
class MosquittoSecurityTest : BrokerSecurityContract() {
    @get:Rule
    val temp = TemporaryFolder()

    private lateinit var mosquitto: MosquittoProcess

    override val alice = "alice"
    override val bob = "bob"
    override val mallory = "mallory"
    override val address: BrokerAddress get() = mosquitto.address
    override val refusesForeignClientIds = false // nothing in mosquitto.conf(5) binds a client id to a user but use_username_as_clientid
    override val refusesRetainedInboxPublishes = false // acl_file has no rule for retained publishes
    override val sharesQueues = false // no per-sender limit in mosquitto.conf(5)
    override val brokerName get() = "Mosquitto ${mosquitto.version}"

    override fun password(user: String): String = "$user-secret"

    override fun brokerLog(): String = mosquitto.log()

    @Before
    fun startMosquitto() {
        MosquittoProcess.assumeInstalled()
        mosquitto = MosquittoProcess(temp.root, listOf(alice, bob, mallory).associateWith(::password))
        mosquitto.start()
    }

    /**
     * Why the shipped configuration leaves `use_username_as_clientid` out: with it, Mosquitto 2.0.11 refuses a CONNECT
     * without a user name after taking its client id, and its error path then removes the session of that id from its
     * client index (src/handle_connect.c, `handle__connect`: this branch goes to `handle_connect_error` with
     * `context->id` set, where the password check sets it to NULL first "so we don't later try and remove the client
     * from the by_id hash table"). Every session's client id is its user name then, so one CONNECT naming bob stops bob
     * receiving anything, queued or live, until the broker restarts: his next session's subscription is merged into
     * the removed one's, which nobody reads. Should this start failing, Mosquitto fixed it: say so in docs/security.md.
     */
    @Test
    fun withUseUsernameAsClientid_oneUserlessConnectNamingBob_silencesBobUntilRestart() {
        MosquittoProcess.assumeVersion2011()
        stopMosquitto()
        mosquitto = MosquittoProcess(temp.newFolder(), listOf(alice, bob).associateWith(::password), listenerOptions = listOf("use_username_as_clientid true"))
        mosquitto.start()
        runBlocking { connected(bob).disconnect() }
        assertEquals(Mqtt3ConnAckReturnCode.NOT_AUTHORIZED, TestClients.returnCodeOf { raw(null, clientId = bob) })
        val silenced = LinkedBlockingQueue<InboxEvent>()
        clients.messenger(MqttSettings(address, bob, password(bob), TestDevices.of(bob), reconnectPolicy = FAST_RECONNECT)) { silenced.put(it) }
        runBlocking { connected(alice).send(bob, ChatMessage.compose(alice, "sent to the removed session")) }
        assertEquals(null, silenced.poll(3, TimeUnit.SECONDS))
        disconnectClients()
        mosquitto.restart()
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        val afterRestart = ChatMessage.compose(alice, "after the restart")
        runBlocking { connected(alice).send(bob, afterRestart) }
        // What was sent to the removed session may come first.
        generateSequence { bobInbox.awaitEvent() }.first { it == InboxEvent.MessageReceived(afterRestart) }
    }

    @After
    fun stopMosquitto() {
        disconnectClients()
        if (::mosquitto.isInitialized) mosquitto.stop()
    }
}
