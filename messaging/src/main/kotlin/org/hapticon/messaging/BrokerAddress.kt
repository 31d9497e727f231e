package org.hapticon.messaging

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
