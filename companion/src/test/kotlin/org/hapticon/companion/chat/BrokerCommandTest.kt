package org.hapticon.companion.chat

import org.hapticon.companion.cli.Console
import kotlinx.coroutines.runBlocking
import org.hapticon.companion.cli
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.broker.AclFile
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.DeviceId
import org.hapticon.messaging.mqtt.MqttSettings
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.io.StringReader
import java.net.InetAddress
import java.net.ServerSocket
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

class BrokerCommandTest {
    @get:Rule
    val temp = TemporaryFolder()

    @Test
    fun broker_firstRunThenAddUser_authenticatesUsersAndCarriesTheirMessages() {
        val port = ServerSocket(0, 1, InetAddress.getByName("127.0.0.1")).use { it.localPort }
        val data = temp.newFolder("broker")
        val first = Captured()
        runBroker(listOf("--port", port.toString(), "--data", data.path), Console(first.stream, Captured().stream)) {}
        assertEquals(
            listOf(
                "broker: no users yet in ${File(data, "passwd")}; nobody can connect until you add one:",
                "broker:   hapticon broker adduser NAME --data $data",
                "broker: listening on tcp://127.0.0.1:$port (users ${File(data, "passwd")}, ACL ${File(data, "aclfile")}), store in ${File(data, "store")}; Ctrl-C stops it",
                "broker: reachable from this machine only; --host ADDRESS (e.g. this laptop's Wi-Fi address) lets phones in",
            ),
            first.lines,
        )
        assertEquals(AclFile.DEFAULT_TEXT, File(data, "aclfile").readText())
        for (user in listOf("alice", "bob")) {
            val added = Captured()
            runBroker(listOf("adduser", user, "--data", data.path), Console(added.stream, Captured().stream), StringReader("$user-secret\n"))
            assertEquals(listOf("broker: $user can connect now (users file ${File(data, "passwd")})"), added.lines)
        }

        val out = Captured()
        val received = LinkedBlockingQueue<InboxEvent>()
        var arrived: InboxEvent? = null
        var impostor: Throwable? = null
        val message = ChatMessage.compose("alice", "through the command's broker")
        runBroker(listOf("--port", port.toString(), "--data", data.path), Console(out.stream, Captured().stream)) {
            runBlocking {
                val address = BrokerAddress("127.0.0.1", port)
                impostor = runCatching { MqttMessenger(MqttSettings(address, "alice", "guess", DeviceId.generate())).connect { } }.exceptionOrNull()
                val bob = MqttMessenger(MqttSettings(address, "bob", "bob-secret", DeviceId.generate()))
                val alice = MqttMessenger(MqttSettings(address, "alice", "alice-secret", DeviceId.generate()))
                bob.connect { received.put(it) }
                alice.connect { }
                alice.send("bob", message)
                arrived = received.poll(WAIT_SECONDS, TimeUnit.SECONDS)
                alice.disconnect()
                bob.disconnect()
            }
        }
        assertEquals("broker: 2 user(s): alice, bob", out.lines.first())
        // The invite link a phone opens, for this machine's LAN address when it has one (with a --host hint).
        lanAddress()?.let { address ->
            val invite = out.lines.single { it.startsWith("invite: ") }
            assertEquals(true, invite.startsWith("invite: hapticon://invite?broker=tcp%3A%2F%2F$address%3A$port"))
        }
        assertEquals(InboxEvent.MessageReceived(message), arrived)
        assertEquals("cannot connect to tcp://127.0.0.1:$port as alice: bad user name or password", impostor?.message)
    }

    @Test
    fun broker_allowAnonymous_warnsLoudlyAndLetsAnyoneIn() {
        val port = ServerSocket(0, 1, InetAddress.getByName("127.0.0.1")).use { it.localPort }
        val out = Captured()
        val err = Captured()
        var connected = false
        runBroker(listOf("--port", port.toString(), "--data", temp.newFolder().path, "--allow-anonymous"), Console(out.stream, err.stream)) {
            runBlocking {
                val anyone = MqttMessenger(MqttSettings(BrokerAddress("127.0.0.1", port), "anyone", null, DeviceId.generate()))
                anyone.connect { }
                connected = true
                anyone.disconnect()
            }
        }
        assertEquals(true, connected)
        assertEquals(
            "broker: WARNING --allow-anonymous: any client that reaches 127.0.0.1:$port connects without a password, reads every inbox and sends as anyone. Use it for a throw-away local test only.",
            err.lines.first(),
        )
        assertEquals(true, out.lines.first().contains("(ANONYMOUS)"))
    }

    @Test
    fun brokerAddUser_badNameOrNoPassword_exitsTwoWithOneLine() {
        val data = temp.newFolder().path
        assertEquals(
            listOf("hapticon: the user name must be 1..32 letters, digits, '.', '_' or '-', starting with a letter or digit; got 'a/b'"),
            cli("broker", "adduser", "a/b", "--data", data).stderrLines,
        )
        assertEquals(listOf("hapticon: broker adduser needs a user name"), cli("broker", "adduser", "--data", data).stderrLines)
    }

    @Test
    fun brokerAddUser_generate_printsAHundredBitPasswordOnce_andStoresItWithTheRoundsAsked() {
        val data = temp.newFolder()
        val out = Captured()
        runBroker(listOf("adduser", "p01", "--data", data.path, "--generate", "--iterations", "101"), Console(out.stream, Captured().stream), StringReader(""))
        val password = out.lines.first().removePrefix("broker: password of p01: ").removeSuffix(" (shown once; give it to p01)")
        assertEquals(true, password.matches(Regex("[a-z2-7]{5}(-[a-z2-7]{5}){3}")))
        assertEquals("broker: p01 can connect now (users file ${File(data, "passwd")})", out.lines[1])
        val line = File(data, "passwd").readLines().single()
        assertEquals(true, line.startsWith("p01:\$7\$101\$"))
        assertEquals(true, org.hapticon.messaging.broker.PasswordFile(File(data, "passwd")).verify("p01", password.toByteArray()))
        assertEquals(
            listOf("hapticon: --generate excludes --password-file"),
            cli("broker", "adduser", "p02", "--data", data.path, "--generate", "--password-file", "x").stderrLines,
        )
        assertEquals(listOf("hapticon: --iterations must be in 1..10000000, got 0"), cli("broker", "adduser", "p02", "--data", data.path, "--iterations", "0").stderrLines)
    }

    @Test
    fun broker_portTakenOrInvalid_exitsTwoWithOneLine() {
        ServerSocket(0, 1, InetAddress.getByName("127.0.0.1")).use { taken ->
            val result = cli("broker", "--port", taken.localPort.toString(), "--data", temp.newFolder().path)
            assertEquals(2, result.exitCode)
            assertEquals(
                "hapticon: cannot start the broker: cannot listen on 127.0.0.1:${taken.localPort}: Address already in use",
                result.stderrLines.single().substringBefore(" (Bind failed)"),
            )
        }
        assertEquals(listOf("hapticon: --port must be in 1..65535, got 70000"), cli("broker", "--port", "70000").stderrLines)
        assertEquals(listOf("hapticon: --port must be a whole number, got 'x'"), cli("broker", "--port", "x").stderrLines)
    }
}
