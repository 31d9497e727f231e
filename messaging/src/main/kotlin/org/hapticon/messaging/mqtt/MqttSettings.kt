package org.hapticon.messaging.mqtt

import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.RetryPolicy
import org.hapticon.messaging.Topics

/**
 * How an [MqttMessenger] connects.
 *
 * The MQTT client id is `USER:DEVICE` ([clientId]): each device of a user has its own persistent session, so
 * two devices both receive what is sent to the user and never take each other's session over. [device] is a
 * secret kept on the device ([DeviceId]): nobody can present another's client id (the embedded broker also
 * refuses a client id that is not the authenticated user's).
 *
 * @property broker where to connect.
 * @property user the user name (see [Topics.isValidUserName]); also the MQTT user name and the first half of the client id.
 * @property password the MQTT password, or null for a broker started with `--allow-anonymous` or when
 *   [clientCertificate] authenticates. Sent in clear text unless [BrokerAddress.tls].
 * @property device this device's session of [user], kept from one run to the next ([DeviceId.loadOrCreate]): a new
 *   one starts an empty session.
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
    val device: DeviceId,
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

    /** The MQTT client id: `USER:DEVICE`, as the embedded broker requires. */
    val clientId: String get() = "$user:${device.value}"

    /** Omits the password and most of the device id. */
    override fun toString(): String =
        "MqttSettings(broker=$broker, user=$user, password=${if (password == null) "none" else "***"}, device=$device, keepAliveSeconds=$keepAliveSeconds" +
            (if (clientCertificate != null) ", clientCertificate=${clientCertificate.user}" else "") +
            (if (trustedCertificates.isNotEmpty()) ", trustedCertificates=${trustedCertificates.size}" else "") + ")"
}
