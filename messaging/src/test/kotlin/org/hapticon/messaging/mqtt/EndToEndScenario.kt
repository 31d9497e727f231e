package org.hapticon.messaging.mqtt

import org.hapticon.testing.InMemoryOutbox
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.delay
import kotlinx.coroutines.launch
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.BoundedDeduplicator
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.OutboxSender
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.hapticon.messaging.RetryPolicy
import org.junit.Assert.assertEquals
import java.util.Collections
import java.util.concurrent.atomic.AtomicInteger

/**
 * The whole end-to-end delivery chain under a broker failure: alice's outbox keeps every message until
 * bob's delivered receipt confirms it and sends again what stays unconfirmed; bob, offline meanwhile, comes
 * back, shows each id once (deduplication) and acknowledges every copy with a receipt. Every one of [count]
 * messages must be shown exactly once and alice's outbox must end empty.
 *
 * @param connect connects a messenger for a user (alice or bob) with a listener.
 */
class EndToEndScenario(private val alice: String, private val bob: String, private val connect: (String, InboxListener) -> MqttMessenger) {
    /** Deliveries bob saw, and the ids he showed (first seen), in order. */
    val deliveries = AtomicInteger()
    val shown: MutableList<String> = Collections.synchronizedList(mutableListOf())

    /** Runs it with [count] messages; [fail] breaks the broker once half of them were acknowledged by it. */
    fun run(count: Int, fail: () -> Unit) = runBlocking {
        connect(bob) { }.disconnect() // bob's session exists; he is offline from here
        val outbox = InMemoryOutbox()
        lateinit var sender: OutboxSender
        val aliceMessenger = connect(alice) { event ->
            if (event is InboxEvent.ReceiptReceived) runBlocking { sender.confirm(event.receipt) }
        }
        sender = OutboxSender(
            outbox, aliceMessenger, RetryPolicy(initialDelayMillis = 50, maxDelayMillis = 500), Clock.SYSTEM,
            sendTimeoutMillis = 2_000, receiptTimeoutMillis = 3_000, maxResendDelayMillis = 10_000,
        )
        val messages = List(count) { ChatMessage.compose(alice, "message $it", icon = HapticIcon.KNOCK.takeIf { _ -> it % 10 == 0 }) }
        for (m in messages) outbox.enqueue(bob, m)
        val sending = launch(Dispatchers.Default) { sender.run() }
        withTimeout(120_000) {
            while (outbox.pending().count { it.awaitingReceipt } < count / 2) delay(1)
            fail()
            while (outbox.pending().any { !it.awaitingReceipt }) delay(10) // the broker acknowledged every one
        }
        // bob comes back: shows each id once, acknowledges every copy (a lost receipt must not leave it pending).
        val deduplicator = BoundedDeduplicator()
        lateinit var bobMessenger: MqttMessenger
        bobMessenger = connect(bob) { event ->
            if (event !is InboxEvent.MessageReceived) return@connect
            deliveries.incrementAndGet()
            val message = event.message
            if (deduplicator.firstSeen(message.id)) shown += message.id
            runBlocking { runCatching { bobMessenger.send(message.sender, Receipt(message.id, bob, ReceiptState.DELIVERED, System.currentTimeMillis())) } }
        }
        withTimeout(120_000) { while (outbox.pending().isNotEmpty()) delay(10) }
        sending.cancelAndJoin()
        assertEquals(count, shown.size)
        assertEquals(messages.map { it.id }.toSet(), shown.toSet())
    }
}
