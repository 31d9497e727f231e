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
 * The MQTT client id is `hapticon-<user>-<deviceId>`, fixed per user and device, so the broker keeps one
 * persistent session per device: messages queued while the device is offline wait for that device. Two
 * clients with the same user and device id take the session from each other; give each device its own id.
 *
 * @property broker where to connect.
 * @property user the user name (see [Topics.isValidUserName]); also the MQTT user name when [password] is set.
 * @property deviceId a stable id of this installation, same rules as a user name.
 * @property password the MQTT password, or null for a broker that allows anonymous clients. Sent in clear
 *   text unless [BrokerAddress.tls].
 * @property keepAliveSeconds MQTT keep-alive: how soon a dead connection is noticed.
 * @property reconnectPolicy delays between reconnection attempts.
 */
public data class MqttSettings(
    val broker: BrokerAddress,
    val user: String,
    val deviceId: String,
    val password: String? = null,
    val keepAliveSeconds: Int = 30,
    val reconnectPolicy: RetryPolicy = RetryPolicy(initialDelayMillis = 250, maxDelayMillis = 30_000),
) {
    init {
        Topics.requireUserName(user)
        require(Topics.isValidUserName(deviceId)) { "device id must follow the user-name rules, was \"$deviceId\"" }
        require(keepAliveSeconds in 1..65_535) { "keepAliveSeconds must be in 1..65535, was $keepAliveSeconds" }
    }

    /** The MQTT client id: `hapticon-<user>-<deviceId>`. */
    val clientId: String get() = "hapticon-$user-$deviceId"

    /** Omits the password. */
    override fun toString(): String =
        "MqttSettings(broker=$broker, user=$user, deviceId=$deviceId, password=${if (password == null) "none" else "***"}, keepAliveSeconds=$keepAliveSeconds)"
}
