package org.hapticon.messaging.mqtt

import com.hivemq.client.mqtt.MqttClient
import com.hivemq.client.mqtt.MqttClientState
import com.hivemq.client.mqtt.MqttGlobalPublishFilter
import com.hivemq.client.mqtt.datatypes.MqttQos
import com.hivemq.client.mqtt.lifecycle.MqttClientDisconnectedContext
import com.hivemq.client.mqtt.mqtt3.Mqtt3AsyncClient
import com.hivemq.client.mqtt.mqtt3.exceptions.Mqtt3ConnAckException
import com.hivemq.client.mqtt.mqtt3.lifecycle.Mqtt3ClientConnectedContext
import com.hivemq.client.mqtt.mqtt3.message.connect.connack.Mqtt3ConnAckReturnCode
import com.hivemq.client.mqtt.mqtt3.message.publish.Mqtt3Publish
import com.hivemq.client.mqtt.mqtt3.message.subscribe.suback.Mqtt3SubAck
import com.hivemq.client.mqtt.mqtt3.message.subscribe.suback.Mqtt3SubAckReturnCode
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.NonCancellable
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.future.await
import kotlinx.coroutines.withContext
import kotlinx.coroutines.withTimeoutOrNull
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.HandPose
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.MessageLimits
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.Topics
import org.hapticon.messaging.e2e.E2eException
import org.hapticon.messaging.e2e.EndToEnd
import java.nio.charset.StandardCharsets
import java.util.concurrent.CompletableFuture
import java.util.concurrent.ExecutorService
import java.util.concurrent.Executors
import java.util.concurrent.ScheduledExecutorService
import java.util.concurrent.TimeUnit
import java.util.concurrent.atomic.AtomicBoolean
import java.util.logging.Level
import java.util.logging.Logger

/**
 * A [Messenger] over MQTT 3.1.1 with the HiveMQ client: QoS 1 for inbox payloads (hand poses QoS 0), everyone's
 * retained capabilities and keys read at QoS 0, a persistent session (cleanSession=false) under the client id of
 * [MqttSettings.clientId] (this device's own), the inbox at
 * `hapticon/v1/inbox/<user>/+` (see [Topics]) and everyone's capabilities at `hapticon/v1/capabilities/+`.
 * What this user sends goes to `hapticon/v1/inbox/<recipient>/<user>`.
 *
 * Incoming payloads are decoded by [MessageCodec] on a delivery thread of this messenger (never on the
 * network thread) and acknowledged to the broker only after the listener returned. One instance connects
 * once; make a new one to connect again.
 *
 * With [EndToEnd] protection the broker sees only sealed payloads on inbox topics (see docs/security.md);
 * capabilities stay in clear (they describe a phone's vibrator to everyone).
 */
public class MqttMessenger(
    private val settings: MqttSettings,
    /**
     * End-to-end protection, or null for none: with it every inbox payload is sealed for its recipient and
     * must arrive sealed ([EndToEnd]), this user's keys are retained at `hapticon/v1/keys/<user>` on every
     * connection and everyone's are read from `hapticon/v1/keys/+`.
     */
    private val e2e: EndToEnd? = null,
) : Messenger {
    override val user: String = settings.user

    private val mutableState = MutableStateFlow<ConnectionState>(ConnectionState.Disconnected)
    override val state: StateFlow<ConnectionState> = mutableState.asStateFlow()

    private val started = AtomicBoolean()
    @Volatile private var closing = false
    @Volatile private var client: Mqtt3AsyncClient? = null
    @Volatile private var subscribedOnce = false
    // Completes when the next reconnection attempt may start: after the backoff delay, or at once on reconnectNow.
    @Volatile private var nextAttempt: CompletableFuture<Unit>? = null
    private val inboxTopic = Topics.inboxFilter(settings.user)

    // One thread, so events reach the listener in arrival order, and a blocking listener stalls only the
    // inbox, never the network thread that also carries keep-alives and acknowledgements.
    private val delivery: ExecutorService = Executors.newSingleThreadExecutor { task ->
        Thread(task, "hapticon-inbox-${settings.user}").apply { isDaemon = true }
    }

    override suspend fun connect(listener: InboxListener) {
        check(started.compareAndSet(false, true)) { "connect may be called once per MqttMessenger" }
        val client = buildClient()
        this.client = client
        // Registered before connecting: a resumed session delivers queued messages before any SUBACK.
        client.publishes(MqttGlobalPublishFilter.ALL, { publish -> deliver(publish, listener) }, delivery, true)
        mutableState.value = ConnectionState.Connecting(lastFailure = null)
        // A failed first attempt goes through the disconnected listener, which schedules the next one.
        client.connectWith().cleanSession(false).keepAlive(settings.keepAliveSeconds).send()
        try {
            val settled = state.first { it == ConnectionState.Connected || it is ConnectionState.Failed }
            if (settled is ConnectionState.Failed) {
                disconnect()
                throw MessagingException("cannot connect to ${settings.broker} as ${settings.user}: ${settled.reason}")
            }
        } catch (e: CancellationException) {
            withContext(NonCancellable) { disconnect() }
            throw e
        }
    }

    override suspend fun disconnect() {
        closing = true
        val client = client
        // Also while reconnecting: disconnecting then cancels the scheduled attempt.
        if (client != null && client.state != MqttClientState.DISCONNECTED) {
            try {
                client.disconnect().await()
            } catch (e: Exception) {
                // Already gone (the broker closed it, say): nothing left to close.
                LOG.log(Level.FINE, "disconnect of ${settings.user}", e)
            }
        }
        if (mutableState.value !is ConnectionState.Failed) mutableState.value = ConnectionState.Disconnected
        // Releases a waiting attempt; the client, now disconnected, does not start it.
        nextAttempt?.complete(Unit)
        delivery.shutdown()
    }

    override fun reconnectNow() {
        val waiting = nextAttempt ?: return
        if (!closing && waiting.complete(Unit)) LOG.log(Level.FINE, "${settings.user}: reconnecting now, the network is back")
    }

    /**
     * One UNSUBSCRIBE/UNSUBACK round trip. MQTT 3.1.1 has PINGREQ for this, but the HiveMQ client sends it only
     * from its own keep-alive timer; any control packet resets the broker's keep-alive count (§3.1.2.10), and an
     * UNSUBSCRIBE of a filter this client never subscribed changes nothing: the broker compares filters
     * character by character (§3.10.4) and answers UNSUBACK all the same. The filter is the user's inbox topic
     * from itself, one the ACL lets the user read, so no broker has reason to refuse it. Unlike a publish it
     * reaches nobody else.
     */
    override suspend fun ping(timeoutMillis: Long): Boolean {
        val client = client ?: return false
        if (state.value != ConnectionState.Connected) return false
        return try {
            withTimeoutOrNull(timeoutMillis) {
                client.unsubscribeWith().topicFilter(Topics.inbox(user, user)).send().await()
                true
            } ?: false
        } catch (e: CancellationException) {
            throw e
        } catch (e: Exception) {
            LOG.log(Level.FINE, "keep-alive round trip of ${settings.clientId} failed", e)
            false
        }
    }

    override suspend fun send(recipient: String, message: ChatMessage) {
        publish(Topics.inbox(recipient, user), seal(recipient, MessageCodec.encode(message)), retain = false)
    }

    override suspend fun send(recipient: String, receipt: Receipt) {
        publish(Topics.inbox(recipient, user), seal(recipient, MessageCodec.encode(receipt)), retain = false)
    }

    override suspend fun send(recipient: String, pose: HandPose) {
        publish(Topics.inbox(recipient, user), seal(recipient, MessageCodec.encode(pose)), retain = false, qos = MqttQos.AT_MOST_ONCE)
    }

    override suspend fun publishCapabilities(capabilities: Capabilities) {
        require(capabilities.user == user) { "capabilities of ${capabilities.user} cannot be published by $user" }
        publish(Topics.capabilities(user), MessageCodec.encode(capabilities), retain = true)
    }

    private fun seal(recipient: String, plaintext: ByteArray): ByteArray {
        val e2e = e2e ?: return plaintext
        return try {
            e2e.seal(recipient, plaintext)
        } catch (e: E2eException) {
            // Like any send failure: an outbox keeps the message and tries again (the key may arrive meanwhile).
            throw MessagingException("not sent: ${e.message}", e)
        }
    }

    private suspend fun publish(topic: String, payload: ByteArray, retain: Boolean, qos: MqttQos = MqttQos.AT_LEAST_ONCE) {
        val client = client
        if (client == null || state.value != ConnectionState.Connected) {
            throw MessagingException("not connected (${describe(state.value)})")
        }
        try {
            client.publishWith().topic(topic).qos(qos).retain(retain).payload(payload).send().await()
        } catch (e: CancellationException) {
            throw e
        } catch (e: Exception) {
            throw MessagingException("publish to $topic failed: ${e.message ?: e.javaClass.simpleName}", e)
        }
    }

    private fun buildClient(): Mqtt3AsyncClient {
        var builder = MqttClient.builder()
            .useMqttVersion3()
            .identifier(settings.clientId)
            .serverHost(settings.broker.host)
            .serverPort(settings.broker.port)
            .addConnectedListener { context -> onConnected((context as Mqtt3ClientConnectedContext).connAck.isSessionPresent) }
            .addDisconnectedListener(::onDisconnected)
        if (settings.broker.tls) {
            val certificate = settings.clientCertificate
            builder = if (certificate == null && settings.trustedCertificates.isEmpty()) {
                builder.sslWithDefaultConfig()
            } else {
                // HiveMQ client's MqttClientSslConfigBuilder: a key manager presents the client certificate; a trust
                // manager replaces the system's trust store with the study's CA.
                var ssl = builder.sslConfig()
                if (certificate != null) ssl = ssl.keyManagerFactory(certificate.keyManagerFactory())
                if (settings.trustedCertificates.isNotEmpty()) ssl = ssl.trustManagerFactory(ClientCertificate.trustManagerFactory(settings.trustedCertificates))
                ssl.applySslConfig()
            }
        }
        if (settings.password != null) {
            builder = builder.simpleAuth()
                .username(settings.user)
                .password(settings.password.toByteArray(StandardCharsets.UTF_8))
                .applySimpleAuth()
        }
        return builder.buildAsync()
    }

    private fun onConnected(sessionPresent: Boolean) {
        val client = client ?: return
        if (closing) {
            client.disconnect()
            return
        }
        // A resumed session still has our subscriptions, so a reconnection is ready at once (and does not
        // make the broker resend every retained capabilities message). The first connection of a messenger
        // always subscribes: one round trip, and it picks up subscriptions a newer version of this class
        // added to an old session. A session the broker lost is subscribed again here.
        if (sessionPresent && subscribedOnce) {
            publishKeysThen { mutableState.value = ConnectionState.Connected }
            return
        }
        // Everyone's capabilities and keys at QoS 0: each is a retained message, sent at every subscription, and a
        // broker keeps no QoS 0 message for an offline session (Mosquitto: queue_qos0_messages false; HiveMQ outside
        // its queue limit), so a participant who republishes its own thousands of times cannot fill the queues that
        // hold everyone's inbox messages.
        var subscribe = client.subscribeWith()
            .addSubscription().topicFilter(inboxTopic).qos(MqttQos.AT_LEAST_ONCE).applySubscription()
            .addSubscription().topicFilter(Topics.ALL_CAPABILITIES).qos(MqttQos.AT_MOST_ONCE).applySubscription()
        if (e2e != null) subscribe = subscribe.addSubscription().topicFilter(Topics.ALL_KEYS).qos(MqttQos.AT_MOST_ONCE).applySubscription()
        subscribe.send()
            .whenComplete { subAck: Mqtt3SubAck?, error: Throwable? ->
                when {
                    // The connection dropped meanwhile; the disconnected listener has it in hand.
                    error != null -> LOG.log(Level.FINE, "subscribe of ${settings.user} failed", error)
                    subAck!!.returnCodes.any { it == Mqtt3SubAckReturnCode.FAILURE } -> {
                        mutableState.value = ConnectionState.Failed(
                            "the broker refused the subscription to $inboxTopic or ${Topics.ALL_CAPABILITIES} (check its ACL)",
                        )
                        closing = true
                        client.disconnect()
                    }
                    !closing -> {
                        subscribedOnce = true
                        publishKeysThen { mutableState.value = ConnectionState.Connected }
                    }
                }
            }
    }

    /**
     * Retains this user's public keys (when end-to-end protection is on), then runs [connected]: before this
     * messenger reports itself connected, peers can already seal for it. Every connection publishes them, so a
     * broker that lost its retained messages has them again. A failed publish is left to the disconnect
     * listener (the connection is gone).
     */
    private fun publishKeysThen(connected: () -> Unit) {
        val e2e = e2e ?: return connected()
        val client = client ?: return
        client.publishWith().topic(Topics.keys(user)).qos(MqttQos.AT_LEAST_ONCE).retain(true).payload(e2e.identity.bundle.encoded).send()
            .whenComplete { _, error ->
                if (error == null) {
                    if (!closing) connected()
                } else {
                    LOG.log(Level.FINE, "key publish of ${settings.user} failed", error)
                }
            }
    }

    private fun onDisconnected(context: MqttClientDisconnectedContext) {
        if (closing) {
            context.reconnector.reconnect(false)
            return
        }
        val refusal = permanentRefusal(context.cause)
        if (refusal != null) {
            context.reconnector.reconnect(false)
            mutableState.value = ConnectionState.Failed(refusal)
            return
        }
        // HiveMQ waits for the delay, then for the future (MqttDisconnectUtil): the whole backoff goes into the
        // future, so that reconnectNow can end it early.
        val delay = settings.reconnectPolicy.delayMillis(context.reconnector.attempts + 1)
        val attempt = CompletableFuture<Unit>()
        nextAttempt = attempt
        BACKOFF.schedule({ attempt.complete(Unit) }, delay, TimeUnit.MILLISECONDS)
        context.reconnector.reconnectWhen(attempt) { _, _ -> }.delay(0, TimeUnit.MILLISECONDS)
        mutableState.value = ConnectionState.Connecting(lastFailure = describeFailure(context.cause))
    }

    private fun deliver(publish: Mqtt3Publish, listener: InboxListener) {
        try {
            val size = publish.payload.map { it.remaining() }.orElse(0)
            // The size is known before the bytes are copied out of the client's buffer.
            val event = if (size > MessageLimits.MAX_PAYLOAD_BYTES) {
                InboxDecoding.oversized(publish.topic.toString(), size)
            } else {
                InboxDecoding.decode(user, publish.topic.toString(), publish.payloadAsBytes, e2e, retained = publish.isRetain)
            }
            if (event != null) listener.onInboxEvent(event)
        } catch (e: Exception) {
            LOG.log(Level.WARNING, "inbox listener of ${settings.user} failed; message acknowledged anyway", e)
        } finally {
            publish.acknowledge()
        }
    }

    internal companion object {
        val LOG: Logger = Logger.getLogger(MqttMessenger::class.java.name)

        // One timer for every messenger's backoff; a daemon, so it never keeps a JVM alive.
        private val BACKOFF: ScheduledExecutorService = Executors.newSingleThreadScheduledExecutor { task ->
            Thread(task, "hapticon-mqtt-backoff").apply { isDaemon = true }
        }

        /** Why the broker will never accept this client as configured, or null when trying again may help. */
        fun permanentRefusal(cause: Throwable): String? {
            if (cause !is Mqtt3ConnAckException) return null
            return when (cause.mqttMessage.returnCode) {
                Mqtt3ConnAckReturnCode.BAD_USER_NAME_OR_PASSWORD -> "bad user name or password"
                Mqtt3ConnAckReturnCode.NOT_AUTHORIZED -> "not authorized"
                Mqtt3ConnAckReturnCode.IDENTIFIER_REJECTED -> "client id rejected"
                Mqtt3ConnAckReturnCode.UNSUPPORTED_PROTOCOL_VERSION -> "the broker does not speak MQTT 3.1.1"
                else -> null
            }
        }

        private val REFUSED_CLIENT_CERTIFICATE = Regex(
            "Received fatal alert: (bad_certificate|certificate_unknown|unknown_ca|certificate_expired|certificate_required|certificate_revoked|unsupported_certificate|access_denied)",
        )

        /** One line saying why a connection attempt failed or a connection ended, for people. */
        fun describeFailure(cause: Throwable): String {
            val chain = generateSequence(cause) { it.cause }.take(8).toList()
            chain.firstOrNull { it is javax.net.ssl.SSLException }?.let { tls ->
                // An alert *received* from the broker about certificates means it refused ours (RFC 8446 §6.2): with
                // mutual TLS that is a missing, expired or foreign client certificate. A broker certificate we do
                // not trust fails here instead, with a CertificateException of our own.
                val alert = tls.message?.let { REFUSED_CLIENT_CERTIFICATE.find(it) }?.groupValues?.get(1)
                if (alert != null) {
                    return "TLS: the broker refused this client's certificate (missing, expired, or not signed by the broker's CA) [$alert]"
                }
                val untrusted = chain.any { it is java.security.cert.CertificateException || it.javaClass.simpleName == "CertPathBuilderException" }
                return if (untrusted) "TLS: the broker's certificate is not trusted (${tls.message})" else "TLS handshake failed: ${tls.message}"
            }
            chain.firstOrNull { it is java.net.ConnectException }?.let { return "connection refused: nothing accepts connections there (${it.message})" }
            chain.firstOrNull { it is java.net.UnknownHostException }?.let { return "unknown host ${it.message}" }
            return cause.message ?: cause.javaClass.simpleName
        }

        fun describe(state: ConnectionState): String = when (state) {
            ConnectionState.Disconnected -> "disconnected"
            ConnectionState.Connected -> "connected"
            is ConnectionState.Connecting -> "connecting" + (state.lastFailure?.let { ": $it" } ?: "")
            is ConnectionState.Failed -> "failed: ${state.reason}"
        }
    }
}
