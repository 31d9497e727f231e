package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.mqtt3.Mqtt3BlockingClient
import kotlinx.coroutines.runBlocking
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.broker.AclFile
import org.hapticon.messaging.broker.BrokerLimits
import org.hapticon.messaging.broker.BrokerSecurity
import org.hapticon.messaging.broker.BrokerTls
import org.hapticon.messaging.broker.CertificateAuthority
import org.hapticon.messaging.broker.ClientCertificates
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.broker.PasswordFile
import org.junit.rules.ExternalResource
import java.io.File
import java.nio.file.Files
import java.util.concurrent.atomic.AtomicInteger

/**
 * The embedded broker for a test, and the messengers and raw clients the test made (disconnected after
 * it). A start costs a second or more (five in a cold JVM) and a stop 4.5 s, so the tests of this module
 * share one broker ([SharedBroker]) and keep apart by using their own user names ([uniqueUser]). A test
 * may restart it: the others reconnect. A test that retains a message deletes it before it ends (an empty
 * retained publish), so later tests do not receive it. Every start goes through [OneBrokerAtATime].
 */
class BrokerFixture : ExternalResource() {
    val broker: EmbeddedBroker get() = SharedBroker.instance
    private val messengers = mutableListOf<MqttMessenger>()
    private val rawClients = mutableListOf<Mqtt3BlockingClient>()

    val address: BrokerAddress get() = BrokerAddress(EmbeddedBroker.HOST, broker.port)

    override fun before() {
        // A test that stopped it may have failed before starting it again; another test class may have run its own.
        OneBrokerAtATime.start(broker)
    }

    override fun after() {
        runBlocking { messengers.forEach { it.disconnect() } }
        rawClients.forEach { runCatching { it.disconnect() } }
    }

    /** A messenger for [user] (registered in the broker's password file), not yet connected. */
    fun messenger(user: String): MqttMessenger =
        MqttMessenger(MqttSettings(address, user, SharedBroker.register(user), TestDevices.of(user), reconnectPolicy = FAST_RECONNECT)).also { messengers += it }

    /** A messenger for [user], connected with [listener]. */
    fun connected(user: String, listener: InboxListener): MqttMessenger =
        messenger(user).also { runBlocking { it.connect(listener) } }

    /**
     * A bare MQTT client, authenticated as [user] (client id [clientId]), that can attempt anything the
     * broker lets it: the hostile third user.
     */
    fun rawClient(user: String, clientId: String = TestDevices.clientId(user)): Mqtt3BlockingClient {
        val client = MqttClient.builder().useMqttVersion3().identifier(clientId).serverHost(EmbeddedBroker.HOST).serverPort(broker.port)
            .simpleAuth().username(user).password(SharedBroker.register(user).toByteArray()).applySimpleAuth()
            .buildBlocking()
        client.connect()
        rawClients += client
        return client
    }
}

/**
 * One embedded broker for every test in this JVM, started on first use, enforcing the shipped ACL and a
 * password file that [register] fills; its store is deleted at exit. Besides the plain listener it has two TLS
 * listeners with [ca]'s broker certificate: [TLS_REQUIRED] (client certificate required) and [TLS_OPTIONAL].
 */
object SharedBroker {
    private val root: File by lazy {
        Files.createTempDirectory("hapticon-test-broker").toFile().also { dir -> Runtime.getRuntime().addShutdownHook(Thread { dir.deleteRecursively() }) }
    }
    val passwords: PasswordFile by lazy { PasswordFile(File(root, "passwd")) }

    /** The study CA whose users' certificates the TLS listeners accept; its server certificate names 127.0.0.1. */
    val ca: CertificateAuthority by lazy { CertificateAuthority.init(File(root, "ca"), "Hapticon test CA", emptyList()) }

    /** The index of the TLS listener that requires a client certificate, and of the one where it is optional. */
    const val TLS_REQUIRED = 0
    const val TLS_OPTIONAL = 1

    val instance: EmbeddedBroker by lazy {
        val acl = File(root, "aclfile").apply { writeText(AclFile.DEFAULT_TEXT) }
        val tls = listOf(ClientCertificates.REQUIRED, ClientCertificates.OPTIONAL).map { mode ->
            BrokerTls(0, EmbeddedBroker.HOST, ca.serverCertificateFile, ca.serverKeyFile, ca.certificateFile, mode)
        }
        // Every test connects from 127.0.0.1, and several send wrong passwords on purpose: with the default of 10
        // failed logins per address, new users of later tests would wait for the address to regain one.
        // EmbeddedLoginFloodTest runs the default limits on a broker of its own.
        val limits = BrokerLimits(failedLoginsPerSource = 10_000)
        EmbeddedBroker(File(root, "store"), security = BrokerSecurity.Authenticated(passwords.file, acl), tls = tls, limits = limits)
            .also { OneBrokerAtATime.start(it) }
    }

    /** Adds [user] to the password file (once) and returns its password, `<user>-secret`. */
    @Synchronized
    fun register(user: String): String {
        val password = "$user-secret"
        // Few PBKDF2 rounds: the tests connect hundreds of times; the format is the same.
        if (user !in registered) passwords.add(user, password.toCharArray(), iterations = 1_000)
        registered += user
        return password
    }

    private val registered = mutableSetOf<String>()
}

/**
 * Starts a test's embedded broker after stopping whichever other one runs in this JVM. Two HiveMQ CE brokers
 * must not run at once in one process: each start sets the process-wide publish counter (the static
 * `PUBLISH.PUBLISH_COUNTER`) to one past the highest payload id in its own store
 * (`PublishPayloadRocksDBLocalPersistence.init`), so a second broker started on a fresh store sends the first
 * one's counter back to 1. The first then hands out payload ids it still holds (a retained message, a queued
 * one), and `PublishPayloadPersistenceImpl.add` keeps the stored payload for a known id: subscribers get an
 * older message in place of the new one (docs/security.md, "Known weaknesses"). One broker stopped and started
 * again is safe: its start counts past everything its store holds.
 */
object OneBrokerAtATime {
    private var current: EmbeddedBroker? = null

    /** Stops the broker started before (if another and still running), then starts [broker]. */
    @Synchronized
    fun start(broker: EmbeddedBroker) {
        current?.takeIf { it !== broker }?.stop()
        broker.start()
        current = broker
    }
}

/**
 * One device id per user name in this JVM: a test's messengers of one user share a session, as one device's would;
 * a second device of that user needs an id of its own ([DeviceId.generate]).
 */
object TestDevices {
    private val ids = java.util.concurrent.ConcurrentHashMap<String, DeviceId>()

    fun of(user: String): DeviceId = ids.computeIfAbsent(user) { DeviceId.generate() }

    /** [user]'s client id, as [MqttSettings.clientId] makes it. */
    fun clientId(user: String): String = "$user:${of(user).value}"
}

private val users = AtomicInteger()

/** [base] with a suffix no other test of this JVM uses, e.g. `alice-7`: users of the shared broker stay apart. */
fun uniqueUser(base: String): String = "$base-${users.incrementAndGet()}"

/** Reconnection delays for tests: a restarted broker is back within seconds, so keep trying briskly. */
val FAST_RECONNECT: RetryPolicy = RetryPolicy(initialDelayMillis = 100, maxDelayMillis = 500)

/** Publishes [payload] at QoS 1 and waits for the broker's acknowledgement. */
fun Mqtt3BlockingClient.publishQos1(topic: String, payload: ByteArray, retain: Boolean = false) {
    publishWith().topic(topic).qos(MqttQos.AT_LEAST_ONCE).retain(retain).payload(payload).send()
}
