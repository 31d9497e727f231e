package org.hapticon.companion.chat

import kotlinx.coroutines.runBlocking
import org.hapticon.companion.Console
import org.hapticon.companion.cli
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.mqtt.BrokerAddress
import org.hapticon.messaging.mqtt.MqttMessenger
import org.hapticon.messaging.mqtt.MqttSettings
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.net.InetAddress
import java.net.ServerSocket
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

class BrokerCommandTest {
    @get:Rule
    val temp = TemporaryFolder()

    @Test
    fun broker_untilStopped_carriesMessagesAndReportsWhereItListens() {
        val port = ServerSocket(0, 1, InetAddress.getByName("127.0.0.1")).use { it.localPort }
        val data = temp.newFolder("store")
        val out = Captured()
        val received = LinkedBlockingQueue<InboxEvent>()
        var arrived: InboxEvent? = null
        val message = ChatMessage.compose("alice", "through the command's broker")
        runBroker(listOf("--port", port.toString(), "--data", data.path), Console(out.stream, Captured().stream)) {
            runBlocking {
                val address = BrokerAddress("127.0.0.1", port)
                val bob = MqttMessenger(MqttSettings(address, "bob", "t"))
                val alice = MqttMessenger(MqttSettings(address, "alice", "t"))
                bob.connect { received.put(it) }
                alice.connect { }
                alice.send("bob", message)
                arrived = received.poll(WAIT_SECONDS, TimeUnit.SECONDS)
                alice.disconnect()
                bob.disconnect()
            }
        }
        // Then the invite link a phone opens, for this machine's LAN address when it has one.
        val invite = lanAddress()?.let { listOf("invite: hapticon://invite?broker=tcp%3A%2F%2F$it%3A$port") } ?: emptyList()
        assertEquals(listOf("broker: listening on tcp://127.0.0.1:$port, store in $data; Ctrl-C stops it") + invite, out.lines)
        assertEquals(InboxEvent.MessageReceived(message), arrived)
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
