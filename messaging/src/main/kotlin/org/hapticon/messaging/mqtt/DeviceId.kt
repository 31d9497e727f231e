package org.hapticon.messaging.mqtt

import org.hapticon.messaging.e2e.Identity
import java.io.File
import java.io.IOException
import java.security.SecureRandom

/**
 * One device's own MQTT session of a user: the random half of its client id `USER:DEVICE` ([MqttSettings.clientId]),
 * 128 bits from [SecureRandom] as 32 lowercase hex digits, made once per user and device and kept.
 *
 * Each device has its own persistent session, so a user's phone and laptop both receive everything sent to that
 * user and never take each other's session over. The id is a secret, because a session must not depend on a client
 * id that anyone may present: Mosquitto 2.0.11 (Debian 12) drops a session from its client index when a CONNECT
 * carrying that session's client id is refused, after which the session receives nothing until the broker restarts
 * (its `context__remove_from_by_id` removes the entry found by id, whichever connection owns it; docs/security.md).
 * Nobody can present an id they cannot guess. The embedded broker also refuses a client id that is not
 * `USER:` + 32 hex digits of the authenticated user.
 *
 * [toString] shows only the last four digits.
 */
public class DeviceId private constructor(
    /** The 32 hex digits. */
    public val value: String,
) {
    override fun equals(other: Any?): Boolean = other is DeviceId && other.value == value

    override fun hashCode(): Int = value.hashCode()

    override fun toString(): String = "DeviceId(…${value.takeLast(4)})"

    public companion object {
        /** Hex digits in a device id: 128 bits. */
        public const val LENGTH: Int = 32

        private val FORMAT = Regex("[0-9a-f]{$LENGTH}")
        private val random = SecureRandom()

        /** A new random device id. */
        public fun generate(): DeviceId {
            val bytes = ByteArray(LENGTH / 2).also(random::nextBytes)
            return DeviceId(bytes.joinToString("") { "%02x".format(it) })
        }

        /** [text] as a device id; throws [IllegalArgumentException] unless it is 32 lowercase hex digits. */
        public fun parse(text: String): DeviceId {
            require(FORMAT.matches(text)) { "a device id is $LENGTH lowercase hex digits" }
            return DeviceId(text)
        }

        /**
         * The device id kept in [file]: read when it exists, else generated and written (mode 600, moved into place
         * whole). Throws [IOException] when the file cannot be read or written or holds something else.
         */
        public fun loadOrCreate(file: File): DeviceId {
            if (file.exists()) {
                val text = file.readText().trim()
                return try {
                    parse(text)
                } catch (e: IllegalArgumentException) {
                    throw IOException("$file: not a device id (${e.message})", e)
                }
            }
            val id = generate()
            Identity.writePrivately(file, (id.value + "\n").toByteArray(Charsets.US_ASCII))
            return id
        }
    }
}
