package org.hapticon.messaging.mqtt

import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.Topics
import java.net.URI
import java.net.URISyntaxException

/**
 * Where the MQTT broker is.
 *
 * @property host its name or address.
 * @property port its TCP port.
 * @property tls whether to connect with TLS (the JVM's or Android's default trust store).
 */
public data class BrokerAddress(val host: String, val port: Int = DEFAULT_PORT, val tls: Boolean = false) {
    init {
        require(host.isNotBlank()) { "broker host must not be blank" }
        require(port in 1..65_535) { "broker port must be in 1..65535, was $port" }
    }

    /** The address as a URL that [parse] reads back, e.g. `tcp://127.0.0.1:1883` or `ssl://example.org:8883`. */
    override fun toString(): String = "${if (tls) "ssl" else "tcp"}://${if (':' in host) "[$host]" else host}:$port"

    public companion object {
        /** The standard MQTT port. */
        public const val DEFAULT_PORT: Int = 1883

        /** The standard MQTT-over-TLS port. */
        public const val DEFAULT_TLS_PORT: Int = 8883

        /**
         * Parses `tcp://HOST[:PORT]` or `mqtt://…` (plain), `ssl://…` or `mqtts://…` (TLS), or a bare
         * `HOST[:PORT]` (plain). The port defaults to 1883, or 8883 with TLS. Throws [IllegalArgumentException]
         * naming the problem for anything else (another scheme, a path, user info, a bad port).
         */
        public fun parse(url: String): BrokerAddress {
            val text = url.trim()
            val withScheme = if ("://" in text) text else "tcp://$text"
            val uri = try {
                URI(withScheme)
            } catch (e: URISyntaxException) {
                throw IllegalArgumentException("not a broker URL: \"$url\" (${e.reason})")
            }
            val tls = when (uri.scheme?.lowercase()) {
                "tcp", "mqtt" -> false
                "ssl", "mqtts" -> true
                else -> throw IllegalArgumentException("broker URL \"$url\": scheme must be tcp, mqtt, ssl or mqtts")
            }
            val host = uri.host ?: throw IllegalArgumentException("broker URL \"$url\" has no host")
            require(uri.rawUserInfo == null) { "broker URL \"$url\": put credentials in the settings, not the URL" }
            require(uri.rawPath.isNullOrEmpty() && uri.rawQuery == null && uri.rawFragment == null) {
                "broker URL \"$url\" must not have a path, query or fragment"
            }
            val port = if (uri.port == -1) (if (tls) DEFAULT_TLS_PORT else DEFAULT_PORT) else uri.port
            return BrokerAddress(host.removePrefix("[").removeSuffix("]"), port, tls)
        }
    }
}

/**
 * How an [MqttMessenger] connects.
 *
 * The MQTT client id is the user name: the broker binds the client id to the authenticated user
 * (Mosquitto `use_username_as_clientid true`; the embedded broker refuses any other id), so nobody can
 * take over another user's persistent session and its queued messages. A user therefore has one session:
 * a second device of the same user that connects takes the session over from the first (MQTT 3.1.1
 * §3.1.4: the server disconnects the existing client with that id).
 *
 * @property broker where to connect.
 * @property user the user name (see [Topics.isValidUserName]); also the MQTT user name and client id.
 * @property password the MQTT password, or null for a broker started with `--allow-anonymous` or when
 *   [clientCertificate] authenticates. Sent in clear text unless [BrokerAddress.tls].
 * @property keepAliveSeconds MQTT keep-alive: how soon a dead connection is noticed.
 * @property reconnectPolicy delays between reconnection attempts.
 * @property clientCertificate the user's certificate for mutual TLS (docs/security.md, "Client certificates"):
 *   needs an `ssl://` broker and must name [user] as its common name.
 * @property trustedCertificates the certificates (a study's own CA) that the broker's certificate must chain
 *   to; empty for the system's trust store. Needs an `ssl://` broker.
 */
public data class MqttSettings(
    val broker: BrokerAddress,
    val user: String,
    val password: String?,
    val keepAliveSeconds: Int = 30,
    val reconnectPolicy: RetryPolicy = RetryPolicy(initialDelayMillis = 250, maxDelayMillis = 30_000),
    val clientCertificate: ClientCertificate? = null,
    val trustedCertificates: List<java.security.cert.X509Certificate> = emptyList(),
) {
    init {
        Topics.requireUserName(user)
        require(keepAliveSeconds in 1..65_535) { "keepAliveSeconds must be in 1..65535, was $keepAliveSeconds" }
        require(clientCertificate == null || broker.tls) { "a client certificate needs a TLS broker address (ssl://…), not $broker" }
        require(trustedCertificates.isEmpty() || broker.tls) { "trusted certificates need a TLS broker address (ssl://…), not $broker" }
        require(clientCertificate == null || clientCertificate.user == user) {
            "the client certificate is for ${clientCertificate?.user}, not $user: the broker takes the user name from the certificate"
        }
    }

    /** The MQTT client id: the user name, as the broker requires. */
    val clientId: String get() = user

    /** Omits the password. */
    override fun toString(): String =
        "MqttSettings(broker=$broker, user=$user, password=${if (password == null) "none" else "***"}, keepAliveSeconds=$keepAliveSeconds" +
            (if (clientCertificate != null) ", clientCertificate=${clientCertificate.user}" else "") +
            (if (trustedCertificates.isNotEmpty()) ", trustedCertificates=${trustedCertificates.size}" else "") + ")"
}
