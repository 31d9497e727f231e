package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.mqtt3.Mqtt3AsyncClient
import com.hivemq.client.mqtt.mqtt3.exceptions.Mqtt3ConnAckException
import org.hapticon.messaging.CollectingListener
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

    private val clients = TestClients()

    @After
    fun disconnectCertificateClients() = clients.close()

    protected fun p12(user: String, by: CertificateAuthority = ca, now: Instant = Instant.now(), validity: Duration = Duration.ofDays(30)): ByteArray =
        by.issueClient(user, PASSWORD.toCharArray(), validity, now)

    protected fun connected(user: String, listener: CollectingListener = CollectingListener()): MqttMessenger {
        val settings = MqttSettings(
            tlsAddress, user, password = null, TestDevices.of(user), reconnectPolicy = FAST_RECONNECT,
            clientCertificate = ClientCertificate.fromPkcs12(p12(user), PASSWORD.toCharArray()),
            trustedCertificates = listOf(ca.certificate),
        )
        return clients.messenger(settings, listener)
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
        return clients.raw(builder)
    }

    private val attacks by lazy {
        ThirdUserAttacks(alice, bob, mallory, ::connected, { clientId -> raw(clientId, p12(mallory)) }, refusesForeignClientIds)
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
        assertRefusedInHandshake(refusal { raw(TestDevices.clientId(bob), p12 = null, user = bob, password = password(bob)) })
    }

    @Test
    fun certificateOfAnotherCa_isRefusedInTheHandshake() {
        val other = CertificateAuthority.init(File(certificates.root, "other-ca"), "Someone else's CA", emptyList())
        assertRefusedInHandshake(refusal { raw(TestDevices.clientId(bob), p12(bob, by = other)) })
    }

    @Test
    fun expiredCertificate_isRefusedByTheClientWithItsDate_andByTheBroker() {
        val expired = p12(bob, now = Instant.now().minus(Duration.ofDays(40)), validity = Duration.ofDays(30))
        val e = refusal { ClientCertificate.fromPkcs12(expired, PASSWORD.toCharArray()) }
        assertTrue(e.message, e is IllegalArgumentException && e.message!!.startsWith("the client certificate of $bob expired on "))
        assertRefusedInHandshake(refusal { raw(bob, expired) })
    }

    @Test
    fun certificateUsers_exchangeMessages_andAThirdReadsNothingOfBobs() =
        attacks.eavesdropping_receivesNothingOfBobs(listOf("#", "hapticon/#", Topics.inboxFilter(bob), Topics.inboxFilter(mallory)))

    @Test
    fun certificateUser_publishingAsAlice_isNeverShownAsAlice() = attacks.forgingAlice_isNeverShownAsAlice()

    @Test
    fun certificateUser_withBobsClientId_cannotTakeBobsSession() = attacks.bobsClientId_cannotTakeBobsSession()

    @Test
    fun settings_refuseACertificateOfAnotherUser() {
        val e = refusal {
            MqttSettings(tlsAddress, bob, null, TestDevices.of(bob), clientCertificate = ClientCertificate.fromPkcs12(p12(mallory), PASSWORD.toCharArray()))
        }
        assertNotNull(e as? IllegalArgumentException)
        assertEquals("the client certificate is for $mallory, not $bob: the broker takes the user name from the certificate", e.message)
    }

    companion object {
        const val PASSWORD = "p12-secret"
    }
}
