package org.hapticon.companion.chat

import org.hapticon.messaging.broker.AclFile
import org.hapticon.messaging.broker.BrokerSecurity
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.broker.PasswordFile
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttSettings
import java.io.File
import java.security.SecureRandom
import java.util.Base64

/**
 * An embedded broker on a free loopback port in [directory], with authentication on (the shipped ACL and a
 * password file holding [users], each with a fresh random password): for the demo and the benchmark, whose
 * users exist only while they run. Not started; [start] it.
 */
class DemoBroker(directory: File, users: List<String>) : AutoCloseable {
    private val passwords: Map<String, String> = users.associateWith { randomPassword() }
    private val devices: Map<String, DeviceId> = users.associateWith { DeviceId.generate() }

    /** The broker itself. */
    val broker: EmbeddedBroker

    init {
        val passwordFile = PasswordFile(File(directory, "passwd"))
        // A few rounds suffice for throw-away passwords of 128 random bits; the format is the real one.
        for ((user, password) in passwords) passwordFile.add(user, password.toCharArray(), iterations = 1_000)
        val acl = File(directory, "aclfile").apply { writeText(AclFile.DEFAULT_TEXT) }
        broker = EmbeddedBroker(File(directory, "store"), security = BrokerSecurity.Authenticated(passwordFile.file, acl))
    }

    /** Starts the broker; see [EmbeddedBroker.start]. */
    fun start(): DemoBroker = apply { broker.start() }

    /** Where the running broker listens. */
    val address: BrokerAddress get() = BrokerAddress(EmbeddedBroker.HOST, broker.port)

    /** How [user] connects: its user name, password and one device of its own. */
    fun settings(user: String): MqttSettings = MqttSettings(address, user, passwords.getValue(user), devices.getValue(user))

    override fun close(): Unit = broker.stop()

    private companion object {
        val random = SecureRandom()

        fun randomPassword(): String = Base64.getUrlEncoder().withoutPadding().encodeToString(ByteArray(16).also(random::nextBytes))
    }
}
