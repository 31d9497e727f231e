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
import org.hapticon.messaging.broker.CertificateAuthority
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotNull
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.ByteArrayInputStream
import java.io.File
import java.security.KeyStore
import java.time.Duration
import java.time.Instant
import java.util.concurrent.ExecutionException
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit
import javax.net.ssl.KeyManagerFactory

/**
 * Client certificates (mutual TLS) on a broker listener that requires one, signed by [ca]: the certificate's
 * common name is the user, bound to the client id, held to the same ACL as password users. Run against the
 * embedded broker ([EmbeddedClientCertificateTest]) and a real Mosquitto with the shipped configuration's
 * certificate listener ([MosquittoClientCertificateTest]).
 */
abstract class ClientCertificateContract {
    @get:Rule
    val certificates = TemporaryFolder()

    protected abstract val alice: String
    protected abstract val bob: String
    protected abstract val mallory: String

    /** The CA whose certificates the listener accepts; its server certificate names 127.0.0.1. */
    protected abstract val ca: CertificateAuthority

    /** The listener that requires a client certificate (`ssl://127.0.0.1:PORT`). */
    protected abstract val tlsAddress: BrokerAddress

    /** [user]'s password on the broker (for showing that a password does not replace the certificate). */
    protected abstract fun password(user: String): String

    /** True when the broker refuses a client id that is not the certificate's user; Mosquitto replaces it. */
    protected abstract val refusesForeignClientIds: Boolean

    private val messengers = mutableListOf<MqttMessenger>()
    private val rawClients = mutableListOf<Mqtt3AsyncClient>()

    @After
    fun disconnectCertificateClients() {
        runBlocking { messengers.forEach { it.disconnect() } }
        rawClients.forEach { runCatching { it.disconnect().get(5, TimeUnit.SECONDS) } }
    }

    protected fun p12(user: String, by: CertificateAuthority = ca, now: Instant = Instant.now(), validity: Duration = Duration.ofDays(30)): ByteArray =
        by.issueClient(user, PASSWORD.toCharArray(), validity, now)

    protected fun connected(user: String, listener: CollectingListener = CollectingListener()): MqttMessenger {
        val settings = MqttSettings(
            tlsAddress, user, password = null, reconnectPolicy = FAST_RECONNECT,
            clientCertificate = ClientCertificate.fromPkcs12(p12(user), PASSWORD.toCharArray()),
            trustedCertificates = listOf(ca.certificate),
        )
        return MqttMessenger(settings).also { messengers += it; runBlocking { it.connect(listener) } }
    }

    /**
     * A bare TLS client with client id [clientId], presenting [p12] (any PKCS#12, expired ones included) when
     * given, and a user name and password when given; connected, or throws why not.
     */
    protected fun raw(clientId: String, p12: ByteArray?, user: String? = null, password: String? = null, address: BrokerAddress = tlsAddress): Mqtt3AsyncClient {
        var ssl = MqttClient.builder().useMqttVersion3().identifier(clientId).serverHost(address.host).serverPort(address.port)
            .sslConfig().trustManagerFactory(ClientCertificate.trustManagerFactory(listOf(ca.certificate)))
        if (p12 != null) {
            val store = KeyStore.getInstance("PKCS12").apply { load(ByteArrayInputStream(p12), PASSWORD.toCharArray()) }
            ssl = ssl.keyManagerFactory(KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm()).apply { init(store, PASSWORD.toCharArray()) })
        }
        var builder = ssl.applySslConfig()
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

    /** What [connect] threw; fails when it connected. */
    protected fun refusal(connect: () -> Unit): Throwable {
        try {
            connect()
        } catch (e: Throwable) {
            if (e is AssertionError) throw e
            return e
        }
        fail("the broker accepted the connection")
        throw AssertionError()
    }

    /** The handshake was refused: TLS ended the connection before any CONNACK, and the one-line reason says so. */
    private fun assertRefusedInHandshake(e: Throwable) {
        assertTrue("expected no CONNACK, got $e", e !is Mqtt3ConnAckException)
        assertEquals(
            "TLS: the broker refused this client's certificate (missing, expired, or not signed by the broker's CA)",
            MqttMessenger.describeFailure(e).substringBefore(" ["),
        )
    }

    @Test
    fun noCertificate_isRefusedInTheHandshake_evenWithBobsPassword() {
        assertRefusedInHandshake(refusal { raw(bob, p12 = null, user = bob, password = password(bob)) })
    }

    @Test
    fun certificateOfAnotherCa_isRefusedInTheHandshake() {
        val other = CertificateAuthority.init(File(certificates.root, "other-ca"), "Someone else's CA", emptyList())
        assertRefusedInHandshake(refusal { raw(bob, p12(bob, by = other)) })
    }

    @Test
    fun expiredCertificate_isRefusedByTheClientWithItsDate_andByTheBroker() {
        val expired = p12(bob, now = Instant.now().minus(Duration.ofDays(40)), validity = Duration.ofDays(30))
        val e = refusal { ClientCertificate.fromPkcs12(expired, PASSWORD.toCharArray()) }
        assertTrue(e.message, e is IllegalArgumentException && e.message!!.startsWith("the client certificate of $bob expired on "))
        assertRefusedInHandshake(refusal { raw(bob, expired) })
    }

    @Test
    fun certificateUsers_exchangeMessages_andAThirdReadsNothingOfBobs() {
        val received = LinkedBlockingQueue<String>()
        val eavesdropper = raw(mallory, p12(mallory))
        for (filter in listOf("#", "hapticon/#", Topics.inboxFilter(bob), Topics.inboxFilter(mallory))) {
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
        assertEquals(Topics.inbox(mallory, alice), received.poll(CollectingListener.WAIT_SECONDS, TimeUnit.SECONDS))
        Thread.sleep(300)
        assertEquals(emptyList<String>(), received.filter { it.contains("/$bob") })
    }

    @Test
    fun certificateUser_publishingAsAlice_isNeverShownAsAlice() {
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        val forger = raw(mallory, p12(mallory))
        val forged = ChatMessage.compose(alice, "I am alice")
        for (topic in listOf(Topics.inbox(bob, mallory), Topics.inbox(bob, alice))) {
            runCatching { forger.publishWith().topic(topic).qos(MqttQos.AT_LEAST_ONCE).payload(MessageCodec.encode(forged)).send().get(10, TimeUnit.SECONDS) }
        }
        val genuine = ChatMessage.compose(alice, "the real alice")
        runBlocking { connected(alice).send(bob, genuine) }
        val events = bobInbox.awaitEvents(2)
        val rejection = (events[0] as InboxEvent.Rejected).rejection
        assertEquals(RejectionReason.INVALID_VALUE to "sender", rejection.reason to rejection.field)
        assertEquals(InboxEvent.MessageReceived(genuine), events[1])
    }

    @Test
    fun certificateUser_withBobsClientId_cannotTakeBobsSession() {
        connected(bob).let { runBlocking { it.disconnect() } }
        val queued = List(2) { ChatMessage.compose(alice, "queued $it") }
        val aliceMessenger = connected(alice)
        runBlocking { queued.forEach { aliceMessenger.send(bob, it) } }
        val code = try {
            raw(bob, p12(mallory)).subscribeWith().topicFilter("#").send().get(10, TimeUnit.SECONDS)
            null
        } catch (e: Mqtt3ConnAckException) {
            e.mqttMessage.returnCode
        }
        if (refusesForeignClientIds) assertEquals(Mqtt3ConnAckReturnCode.IDENTIFIER_REJECTED, code) else assertEquals(null, code)
        val bobInbox = CollectingListener()
        connected(bob, bobInbox)
        assertEquals(queued.map { InboxEvent.MessageReceived(it) }, bobInbox.awaitEvents(2))
    }

    @Test
    fun settings_refuseACertificateOfAnotherUser() {
        val e = refusal {
            MqttSettings(tlsAddress, bob, null, clientCertificate = ClientCertificate.fromPkcs12(p12(mallory), PASSWORD.toCharArray()))
        }
        assertNotNull(e as? IllegalArgumentException)
        assertEquals("the client certificate is for $mallory, not $bob: the broker takes the user name from the certificate", e.message)
    }

    companion object {
        const val PASSWORD = "p12-secret"
    }
}
