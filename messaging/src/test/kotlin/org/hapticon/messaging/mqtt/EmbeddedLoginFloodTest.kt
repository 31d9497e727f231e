package org.hapticon.messaging.mqtt

import kotlinx.coroutines.runBlocking
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.broker.AclFile
import org.hapticon.messaging.broker.BrokerLimits
import org.hapticon.messaging.broker.BrokerSecurity
import org.hapticon.messaging.broker.EmbeddedBroker
import org.hapticon.messaging.broker.PasswordFile
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.util.concurrent.LinkedBlockingQueue

/**
 * The wrong-password flood against the embedded broker as `hapticon broker` runs it: default [BrokerLimits], users
 * added as `hapticon broker adduser` adds them (210,000 PBKDF2 rounds). 32 connections send wrong passwords for bob
 * while alice writes to bob; the broker computes only as many hashes as 127.0.0.1 has failed logins (5) and
 * refuses every other attempt before hashing ("server unavailable"). alice's latency with and without the flood is
 * printed, over the whole flood and over its second half, after those few hashes (figures, not asserted: the
 * machine is shared).
 */
class EmbeddedLoginFloodTest {
    @get:Rule
    val temp = TemporaryFolder()

    private val messengers = mutableListOf<MqttMessenger>()
    private var broker: EmbeddedBroker? = null

    @After
    fun stop() {
        runBlocking { messengers.forEach { it.disconnect() } }
        broker?.stop()
    }

    @Test
    fun thirtyTwoWrongPasswordConnections_costTenHashes_aliceStillWritesToBob() {
        val passwords = PasswordFile(File(temp.root, "passwd"))
        for (user in listOf("alice", "bob")) passwords.add(user, "$user-secret".toCharArray()) // PasswordFile.DEFAULT_ITERATIONS
        val acl = File(temp.root, "aclfile").apply { writeText(AclFile.DEFAULT_TEXT) }
        val limits = BrokerLimits()
        val started = EmbeddedBroker(File(temp.root, "store"), security = BrokerSecurity.Authenticated(passwords.file, acl), limits = limits)
        broker = started
        OneBrokerAtATime.start(started)
        val address = BrokerAddress(EmbeddedBroker.HOST, started.port)
        fun connected(user: String, listener: org.hapticon.messaging.InboxListener) =
            MqttMessenger(MqttSettings(address, user, "$user-secret", TestDevices.of(user), reconnectPolicy = FAST_RECONNECT))
                .also { messengers += it; runBlocking { it.connect(listener) } }
        val bobInbox = LinkedBlockingQueue<Pair<InboxEvent, Long>>()
        connected("bob", LoginFlood.inboxListener(bobInbox))
        val alice = connected("alice") { }
        val baseline = LoginFlood.latencies(alice, "bob", bobInbox, PROBES)

        val flood = LoginFlood(EmbeddedBroker.HOST, started.port, "bob")
        flood.start()
        val underFlood = LoginFlood.latencies(alice, "bob", bobInbox, 2 * PROBES)
        val replies = flood.stop()

        assertEquals(2 * PROBES, underFlood.size)
        val hashed = replies[LoginFlood.BAD_USER_NAME_OR_PASSWORD] ?: 0
        val refused = replies[LoginFlood.SERVER_UNAVAILABLE] ?: 0
        assertTrue("hashed $hashed wrong passwords: $replies", hashed <= limits.failedLoginsPerSource)
        assertTrue("the flood made only $refused attempts: $replies", refused >= 100)
        assertEquals(setOf(LoginFlood.BAD_USER_NAME_OR_PASSWORD, LoginFlood.SERVER_UNAVAILABLE), replies.keys)
        println(
            "wrong-password flood, embedded broker (210,000 PBKDF2 rounds, default limits): alice to bob without it " +
                "${LoginFlood.summary(baseline)}; under 32 connections ${LoginFlood.summary(underFlood)}, its second half " +
                "${LoginFlood.summary(underFlood.drop(PROBES))}; the flood made " +
                "${hashed + refused} attempts, $hashed hashed, $refused refused before hashing",
        )
    }

    private companion object {
        const val PROBES = 20
    }
}
