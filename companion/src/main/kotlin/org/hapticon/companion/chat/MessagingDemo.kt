package org.hapticon.companion.chat

import org.hapticon.companion.cli.AudioSettings
import org.hapticon.companion.cli.WavExport
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.mqtt.MqttMessenger
import java.io.File
import java.nio.file.Files

/**
 * The messaging part of `hapticon demo`: the embedded broker on a free loopback port with authentication
 * on (a password file holding the two demo users with random passwords, and the shipped ACL), alice
 * sends bob a text with the knock icon, bob renders the icon he received to `received-knock.wav` and sends
 * a delivered receipt, which alice receives.
 */
object MessagingDemo {
    /** The message alice sends. */
    const val TEXT: String = "hello from alice"

    /**
     * Runs the exchange, writing `received-knock.wav` into [dir] (which must exist) and reporting each step
     * through [report]. Blocks for a few seconds (the broker's shutdown takes 2). Throws
     * [IllegalStateException] when something other than the expected message or receipt arrives, and
     * [kotlinx.coroutines.TimeoutCancellationException] when nothing does within 20 s.
     */
    fun write(dir: File, report: (String) -> Unit) {
        val store = Files.createTempDirectory("hapticon-demo-broker").toFile()
        try {
            DemoBroker(store, listOf("alice", "bob")).start().use { broker ->
                report("messaging: embedded MQTT broker on ${broker.address}, users alice and bob with passwords, the shipped ACL")
                runBlocking { exchange(broker, dir, report) }
            }
        } finally {
            store.deleteRecursively()
        }
    }

    private suspend fun exchange(broker: DemoBroker, dir: File, report: (String) -> Unit) {
        val aliceInbox = Channel<InboxEvent>(Channel.UNLIMITED)
        val bobInbox = Channel<InboxEvent>(Channel.UNLIMITED)
        val alice = MqttMessenger(broker.settings("alice"))
        val bob = MqttMessenger(broker.settings("bob"))
        try {
            alice.connect { aliceInbox.trySend(it) }
            bob.connect { bobInbox.trySend(it) }
            val sent = ChatMessage.compose("alice", TEXT, icon = HapticIcon.KNOCK)
            alice.send("bob", sent)
            val received = withTimeout(WAIT_MILLIS) { bobInbox.receive() }
            check(received == InboxEvent.MessageReceived(sent)) { "bob expected alice's message, got $received" }
            report("messaging: alice sent bob \"$TEXT\" with ${ChatFormat.icon(HapticIcon.KNOCK)}; bob received it intact")
            report(WavExport.write(sent.icon!!, AudioSettings(), File(dir, "received-knock.wav")))
            val receipt = Receipt(sent.id, "bob", ReceiptState.DELIVERED, System.currentTimeMillis())
            bob.send("alice", receipt)
            val back = withTimeout(WAIT_MILLIS) { aliceInbox.receive() }
            check(back == InboxEvent.ReceiptReceived(receipt)) { "alice expected bob's receipt, got $back" }
            report("messaging: bob's delivered receipt reached alice")
        } finally {
            alice.disconnect()
            bob.disconnect()
        }
    }

    private const val WAIT_MILLIS = 20_000L
}
