package org.hapticon.messaging.broker

import com.hivemq.extension.sdk.api.ExtensionMain
import com.hivemq.extension.sdk.api.async.TimeoutFallback
import com.hivemq.extension.sdk.api.auth.PublishAuthorizer
import com.hivemq.extension.sdk.api.auth.SimpleAuthenticator
import com.hivemq.extension.sdk.api.auth.SubscriptionAuthorizer
import com.hivemq.extension.sdk.api.auth.parameter.PublishAuthorizerInput
import com.hivemq.extension.sdk.api.auth.parameter.PublishAuthorizerOutput
import com.hivemq.extension.sdk.api.auth.parameter.SimpleAuthInput
import com.hivemq.extension.sdk.api.auth.parameter.SimpleAuthOutput
import com.hivemq.extension.sdk.api.auth.parameter.SubscriptionAuthorizerInput
import com.hivemq.extension.sdk.api.auth.parameter.SubscriptionAuthorizerOutput
import com.hivemq.extension.sdk.api.interceptor.publish.PublishInboundInterceptor
import com.hivemq.extension.sdk.api.interceptor.publish.PublishOutboundInterceptor
import com.hivemq.extension.sdk.api.interceptor.publish.parameter.PublishInboundInput
import com.hivemq.extension.sdk.api.interceptor.publish.parameter.PublishInboundOutput
import com.hivemq.extension.sdk.api.interceptor.publish.parameter.PublishOutboundInput
import com.hivemq.extension.sdk.api.interceptor.publish.parameter.PublishOutboundOutput
import com.hivemq.extension.sdk.api.packets.connect.ConnackReasonCode
import com.hivemq.extension.sdk.api.packets.general.MqttVersion
import com.hivemq.extension.sdk.api.packets.general.Qos
import com.hivemq.extension.sdk.api.packets.publish.AckReasonCode
import com.hivemq.extension.sdk.api.parameter.ExtensionStartInput
import com.hivemq.extension.sdk.api.parameter.ExtensionStartOutput
import com.hivemq.extension.sdk.api.parameter.ExtensionStopInput
import com.hivemq.extension.sdk.api.parameter.ExtensionStopOutput
import com.hivemq.extension.sdk.api.services.Services
import org.slf4j.LoggerFactory
import java.io.File
import java.io.IOException
import java.security.MessageDigest
import java.security.SecureRandom
import java.time.Duration
import java.util.concurrent.ConcurrentHashMap
import java.util.concurrent.Executor
import java.util.concurrent.ExecutorService
import java.util.concurrent.Executors
import java.util.concurrent.RejectedExecutionException
import javax.crypto.Mac
import javax.crypto.spec.SecretKeySpec

/** Who may connect to an [EmbeddedBroker] and what they may do. */
public sealed interface BrokerSecurity {
    /**
     * Every client authenticates with a user name and password from [passwordFile] (Mosquitto's format, see
     * [PasswordFile]) or, on a TLS listener that asks for one ([BrokerTls]), with a client certificate of the
     * study's CA whose common name is the user; its client id must be one of its device ids (`USER:` + 32 hex digits,
     * [ClientIds]); it publishes and subscribes only as [aclFile] (Mosquitto's format, see [AclFile]) allows, never a
     * retained message into an inbox. The same rules as companion/mosquitto/mosquitto.conf, plus [BrokerLimits].
     */
    public data class Authenticated(val passwordFile: File, val aclFile: File) : BrokerSecurity

    /**
     * Anyone connects with any client id and reads and writes every topic: the broker's state before
     * authentication existed, for a throw-away local test only. [EmbeddedBroker.start] logs a warning.
     */
    public data object AllowAnonymous : BrokerSecurity
}

/**
 * The HiveMQ extension that enforces a [BrokerSecurity], with the HiveMQ extension SDK: a
 * [SimpleAuthenticator] (registered through `Services.securityRegistry().setAuthenticatorProvider`) decides
 * each CONNECT, one authorizer that is both a [PublishAuthorizer] and a [SubscriptionAuthorizer]
 * decides each PUBLISH and each SUBSCRIBE topic filter (`setAuthorizerProvider`), and [PublishLimiter], a publish
 * inbound and outbound interceptor added to every client (`Services.initializerRegistry().setClientInitializer`),
 * keeps each sender to its share of each recipient's queue ([BrokerLimits]).
 *
 * The client id is bound to the user: a CONNECT whose client id is not `USER:DEVICE` of its own user ([ClientIds])
 * is refused with "identifier rejected", so nobody can take over another user's session. Because of that binding
 * the authorizers and the limiter take the user name from the client id.
 */
internal class SecurityExtension(private val security: BrokerSecurity, private val limits: BrokerLimits) : ExtensionMain {
    private var hashing: ExecutorService? = null

    override fun extensionStart(input: ExtensionStartInput, output: ExtensionStartOutput) {
        when (security) {
            is BrokerSecurity.Authenticated -> {
                val acl = try {
                    AclFile.read(security.aclFile)
                } catch (e: IOException) {
                    output.preventExtensionStartup("ACL file: ${e.message}")
                    return
                }
                val passwords = PasswordFile(security.passwordFile)
                val quota = InboxQuota(limits.inboxShare)
                // The sessions in the store belong to devices that logged in before (client ids are bound to users).
                Services.clientService().iterateAllClients { _, session -> quota.session(session.clientIdentifier, fresh = false) }
                    .whenComplete { _, error -> if (error != null) LOG.warn("cannot list the stored sessions: {}", error.message) }
                // One thread computes password hashes: the extension threads HiveMQ runs every authorizer and
                // interceptor on stay free, and one core stays free for everyone already connected.
                val executor = Executors.newSingleThreadExecutor { task -> Thread(task, "hapticon-password-hash").apply { isDaemon = true } }
                hashing = executor
                val authenticator = PasswordAuthenticator(passwords, LoginThrottle(limits), quota, executor)
                val limiter = PublishLimiter(quota, limits)
                Services.securityRegistry().setAuthenticatorProvider { authenticator }
                Services.securityRegistry().setAuthorizerProvider { AclAuthorizer(acl) }
                Services.initializerRegistry().setClientInitializer { _, context ->
                    context.addPublishInboundInterceptor(limiter)
                    context.addPublishOutboundInterceptor(limiter)
                }
            }
            BrokerSecurity.AllowAnonymous -> {
                Services.securityRegistry().setAuthenticatorProvider { SimpleAuthenticator { _, out -> out.authenticateSuccessfully() } }
            }
        }
    }

    override fun extensionStop(input: ExtensionStopInput, output: ExtensionStopOutput) {
        hashing?.shutdownNow()
        hashing = null
    }

    companion object {
        internal val LOG = LoggerFactory.getLogger(SecurityExtension::class.java)
    }
}

/**
 * Accepts a CONNECT from a client that either showed a client certificate on a TLS listener or gave a user name
 * and its password from [passwords]; either way its client id must be one of its user's device ids ([ClientIds]).
 *
 * A certificate has been checked by the TLS handshake already (signed by the listener's trusted CA, within its
 * validity: HiveMQ's trust store, `client-authentication-mode`); its user is its common name
 * ([CertificateAuthority.userOf]), as Mosquitto's `use_identity_as_username`. The extension SDK hands the
 * certificate over as `ConnectionInformation.getClientTlsInformation().getClientCertificate()`. A certificate
 * user needs no password-file entry; a user name sent with a certificate must be the certificate's.
 *
 * A password is checked against its hash (210,000 PBKDF2 rounds by default: about a quarter of a second of one
 * core) on [hashing], one thread, after [throttle] allowed it: a flood of wrong passwords is refused before any
 * hash once its address or user name spent its failed logins, and never keeps more than one core busy. A password
 * that matched before is recognised by an HMAC under a key of this process (microseconds), so reconnecting devices
 * never wait for the hash nor meet the throttle. The reply to a refused login does not say whether the user exists.
 */
internal class PasswordAuthenticator(
    private val passwords: PasswordFile,
    private val throttle: LoginThrottle,
    private val sessions: InboxQuota,
    private val hashing: Executor,
) : SimpleAuthenticator {
    private class Verified(val hash: String, val mac: ByteArray)

    private val verified = ConcurrentHashMap<String, Verified>()
    private val macKey = SecretKeySpec(ByteArray(32).also(SecureRandom()::nextBytes), "HmacSHA256")

    override fun onConnect(input: SimpleAuthInput, output: SimpleAuthOutput) {
        val connect = input.connectPacket
        val certificate = input.connectionInformation.clientTlsInformation.flatMap { it.clientCertificate }.orElse(null)
        if (certificate != null) {
            val user = CertificateAuthority.userOf(certificate)
            val claimed = connect.userName.orElse(null)
            when {
                user == null -> output.failAuthentication(ConnackReasonCode.NOT_AUTHORIZED, "the client certificate names no user (one CN that is a user name)")
                claimed != null && claimed != user -> output.failAuthentication(ConnackReasonCode.BAD_USER_NAME_OR_PASSWORD, "the user name is not the certificate's")
                !ClientIds.isDeviceOf(user, connect.clientId) -> output.failAuthentication(ConnackReasonCode.CLIENT_IDENTIFIER_NOT_VALID, CLIENT_ID_RULE)
                else -> succeed(output, connect.clientId, connect.cleanStart)
            }
            return
        }
        val user = connect.userName.orElse(null)
        val password = connect.password.orElse(null)?.let { buffer -> ByteArray(buffer.remaining()).also { buffer.duplicate().get(it) } }
        if (user == null || password == null) return output.failAuthentication(ConnackReasonCode.NOT_AUTHORIZED, "a user name and password are required")
        // The rule is the same for every user name, so the reply tells nothing about which exist.
        if (!ClientIds.isDeviceOf(user, connect.clientId)) return output.failAuthentication(ConnackReasonCode.CLIENT_IDENTIFIER_NOT_VALID, CLIENT_ID_RULE)
        val hash = try {
            passwords.hashOf(user)
        } catch (e: IOException) {
            null // an unreadable password file lets nobody in
        }
        if (hash == null) {
            password.fill(0)
            return output.failAuthentication(ConnackReasonCode.BAD_USER_NAME_OR_PASSWORD, BAD_LOGIN)
        }
        val mac = mac(user, password)
        val known = verified[user]
        if (known != null && known.hash == hash && MessageDigest.isEqual(known.mac, mac)) {
            password.fill(0)
            return succeed(output, connect.clientId, connect.cleanStart)
        }
        val source = input.connectionInformation.inetAddress.map { it.hostAddress }.orElse("unknown")
        val permit = when (val decision = throttle.begin(source, user, sessions.isKnown(connect.clientId))) {
            is LoginThrottle.Refusal -> {
                password.fill(0)
                return output.failAuthentication(ConnackReasonCode.SERVER_UNAVAILABLE, decision.reason)
            }
            is LoginThrottle.Permit -> decision
        }
        val async = output.async(HASH_TIMEOUT, TimeoutFallback.FAILURE, ConnackReasonCode.SERVER_UNAVAILABLE, "the password check took too long")
        try {
            hashing.execute {
                var success = false
                try {
                    success = PasswordFile.matches(hash, password)
                    if (success) verified[user] = Verified(hash, mac)
                    try {
                        if (success) succeed(output, connect.clientId, connect.cleanStart) else output.failAuthentication(ConnackReasonCode.BAD_USER_NAME_OR_PASSWORD, BAD_LOGIN)
                    } catch (e: UnsupportedOperationException) {
                        // HASH_TIMEOUT passed while this login waited: HiveMQ has refused it already.
                    }
                } finally {
                    password.fill(0)
                    permit.finish(success)
                    async.resume()
                }
            }
        } catch (e: RejectedExecutionException) {
            permit.finish(false)
            output.failAuthentication(ConnackReasonCode.SERVER_UNAVAILABLE, "the broker is stopping")
            async.resume()
        }
    }

    private fun succeed(output: SimpleAuthOutput, clientId: String, cleanStart: Boolean) {
        sessions.session(clientId, fresh = cleanStart)
        output.authenticateSuccessfully()
    }

    private fun mac(user: String, password: ByteArray): ByteArray = Mac.getInstance("HmacSHA256").run {
        init(macKey)
        update(user.toByteArray(Charsets.UTF_8))
        update(0)
        doFinal(password)
    }

    private companion object {
        const val CLIENT_ID_RULE = "the client id must be USER:DEVICE, this user's name and 32 hex digits"
        const val BAD_LOGIN = "bad user name or password"
        val HASH_TIMEOUT: Duration = Duration.ofSeconds(30)
    }
}

/**
 * Allows a PUBLISH or SUBSCRIBE only when [acl] does, for the user whose client id it is ([ClientIds]); never a
 * retained message on an inbox topic (it would be replayed to the recipient at every subscription, and each replay
 * would earn its sender a delivered receipt: a presence oracle).
 */
internal class AclAuthorizer(private val acl: AclFile) : PublishAuthorizer, SubscriptionAuthorizer {
    override fun authorizePublish(input: PublishAuthorizerInput, output: PublishAuthorizerOutput) {
        val client = input.clientInformation.clientId
        val user = ClientIds.userOf(client)
        val packet = input.publishPacket
        val allowed = user != null && acl.mayPublish(user, client, packet.topic) && !(packet.retain && packet.topic.startsWith(INBOX_PREFIX))
        if (allowed) output.authorizeSuccessfully() else output.failAuthorization()
    }

    override fun authorizeSubscribe(input: SubscriptionAuthorizerInput, output: SubscriptionAuthorizerOutput) {
        val client = input.clientInformation.clientId
        val user = ClientIds.userOf(client)
        if (user != null && acl.maySubscribe(user, client, input.subscription.topicFilter)) output.authorizeSuccessfully() else output.failAuthorization()
    }
}

/** The prefix of every inbox topic, `hapticon/v1/inbox/<recipient>/<sender>` (org.hapticon.messaging.Topics). */
internal const val INBOX_PREFIX = "hapticon/v1/inbox/"

/**
 * Keeps each sender to [BrokerLimits]: a QoS 1 message into a recipient's inbox is held back once the sender has
 * its full share waiting in the recipient's sessions ([InboxQuota]); a retained publish of the sender's own
 * capabilities or keys (each reaches every session of every user) once it spent its [BrokerLimits.retainedPublishes].
 * A held-back message is acknowledged and dropped for an MQTT 3.1.1 client (which has no negative acknowledgement;
 * HiveMQ disconnects it for any other reason code), with QUOTA_EXCEEDED for an MQTT 5 one: the sender's outbox keeps
 * the message until the recipient's receipt and sends it again. Every message sent on to a session is counted off.
 *
 * Runs before the authorizer, so it counts only publishes the ACL will let through: into an inbox under the
 * sender's own name, to its own retained topics.
 */
internal class PublishLimiter(private val quota: InboxQuota, limits: BrokerLimits, nanoTime: () -> Long = System::nanoTime) :
    PublishInboundInterceptor, PublishOutboundInterceptor {
    private val retained = Buckets(limits.retainedPublishes, limits.retainedRefillMillis * 1_000_000, nanoTime)
    private val warned = Buckets(1, 60_000_000_000L, nanoTime)

    override fun onInboundPublish(input: PublishInboundInput, output: PublishInboundOutput) {
        val packet = input.publishPacket
        val sender = ClientIds.userOf(input.clientInformation.clientId) ?: return
        val topic = packet.topic
        val inbox = inbox(topic)
        val held = when {
            inbox != null -> inbox.second == sender && packet.qos != Qos.AT_MOST_ONCE && !packet.retain && !quota.admit(sender, inbox.first)
            packet.retain && (topic == "$CAPABILITIES_PREFIX$sender" || topic == "$KEYS_PREFIX$sender") -> !retained.take(topic)
            else -> false
        }
        if (!held) return
        if (warned.take(sender)) SecurityExtension.LOG.warn("{} exceeds its share: its publishes to {} are dropped (logged once a minute)", sender, topic)
        if (input.connectionInformation.mqttVersion == MqttVersion.V_5) {
            output.preventPublishDelivery(AckReasonCode.QUOTA_EXCEEDED, "over this sender's share; send again later")
        } else {
            output.preventPublishDelivery()
        }
    }

    override fun onOutboundPublish(input: PublishOutboundInput, output: PublishOutboundOutput) {
        val packet = input.publishPacket
        // A redelivery (DUP) was counted off when it first went out.
        if (packet.qos == Qos.AT_MOST_ONCE || packet.dupFlag) return
        val inbox = inbox(packet.topic) ?: return
        quota.sent(input.clientInformation.clientId, inbox.second)
    }

    /** (recipient, sender) of an inbox topic, or null for any other topic. */
    private fun inbox(topic: String): Pair<String, String>? {
        if (!topic.startsWith(INBOX_PREFIX)) return null
        val levels = topic.substring(INBOX_PREFIX.length).split('/')
        return if (levels.size == 2) levels[0] to levels[1] else null
    }

    private companion object {
        const val CAPABILITIES_PREFIX = "hapticon/v1/capabilities/"
        const val KEYS_PREFIX = "hapticon/v1/keys/"
    }
}
