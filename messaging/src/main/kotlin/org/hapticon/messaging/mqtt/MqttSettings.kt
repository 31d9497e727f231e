package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.Topics

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
