package org.hapticon.messaging.mqtt

import kotlinx.coroutines.runBlocking
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.broker.PasswordFile
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Before
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.util.concurrent.LinkedBlockingQueue

/**
 * The wrong-password flood against Mosquitto with the shipped configuration. Mosquitto checks passwords on its one
 * thread and has no setting that limits attempts (mosquitto.conf(5)), so what a flood costs everyone is the hash:
 * measured here with the hashes `mosquitto_passwd` writes (PBKDF2-SHA512, 101 rounds) and with those of
 * `hapticon broker adduser` (210,000 rounds). alice's latency to bob without and under 32 connections is printed
 * (figures, not asserted: the machine is shared); every probe must arrive.
 */
class MosquittoLoginFloodTest {
    @get:Rule
    val temp = TemporaryFolder()

    private lateinit var mosquitto: MosquittoProcess
    private val messengers = mutableListOf<MqttMessenger>()

    @Before
    fun startMosquitto() {
        MosquittoProcess.assumeInstalled()
        mosquitto = MosquittoProcess(temp.root, USERS.associateWith { "$it-secret" })
        mosquitto.start()
    }

    @After
    fun stopMosquitto() {
        disconnect()
        if (::mosquitto.isInitialized) mosquitto.stop()
    }

    private fun disconnect() {
        runBlocking { messengers.forEach { it.disconnect() } }
        messengers.clear()
    }

    @Test
    fun thirtyTwoWrongPasswordConnections_latencyWithMosquittosAndWithSlowHashes() {
        val cheap = measure(probes = 20)
        disconnect()
        mosquitto.stop()
        val passwords = PasswordFile(File(temp.root, "passwd"))
        for (user in USERS) passwords.add(user, "$user-secret".toCharArray()) // 210,000 rounds, replacing mosquitto_passwd's
        mosquitto.start()
        val slow = measure(probes = 3)
        println("wrong-password flood, Mosquitto ${mosquitto.version}, mosquitto_passwd's 101 PBKDF2 rounds: $cheap")
        println("wrong-password flood, Mosquitto ${mosquitto.version}, hapticon broker adduser's 210,000 PBKDF2 rounds: $slow")
    }

    /** alice's latency to bob without and under the flood, and what the flood's attempts got. */
    private fun measure(probes: Int): String {
        val bobInbox = LinkedBlockingQueue<Pair<InboxEvent, Long>>()
        fun connected(user: String, listener: org.hapticon.messaging.InboxListener) =
            MqttMessenger(MqttSettings(mosquitto.address, user, "$user-secret", TestDevices.of(user), reconnectPolicy = FAST_RECONNECT))
                .also { messengers += it; runBlocking { it.connect(listener) } }
        connected("bob", LoginFlood.inboxListener(bobInbox))
        val alice = connected("alice") { }
        val baseline = LoginFlood.latencies(alice, "bob", bobInbox, probes)
        val flood = LoginFlood(MosquittoProcess.HOST, mosquitto.port, "bob")
        flood.start()
        Thread.sleep(1_000)
        val underFlood = LoginFlood.latencies(alice, "bob", bobInbox, probes)
        val replies = flood.stop()
        assertEquals(probes, underFlood.size)
        return "without it ${LoginFlood.summary(baseline)}; under 32 connections ${LoginFlood.summary(underFlood)}; " +
            "${replies.values.sum()} attempts, all hashed (CONNACK codes $replies)"
    }

    private companion object {
        val USERS = listOf("alice", "bob")
    }
}
