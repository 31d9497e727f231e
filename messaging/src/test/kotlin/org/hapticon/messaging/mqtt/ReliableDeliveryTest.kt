package org.hapticon.messaging.mqtt

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
import org.hapticon.messaging.InMemoryOutbox
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.OutboxSender
import org.hapticon.messaging.RetryPolicy
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import java.util.Collections
import java.util.concurrent.atomic.AtomicInteger

/**
 * The whole delivery chain under a broker restart: outbox + retries on the sending side, persistent session
 * + QoS 1 in the broker (whose store must keep what it queued for an offline receiver), deduplication by
 * id on the receiving side. Every one of 1,000 messages must take effect exactly once.
 */
class ReliableDeliveryTest {
    @get:Rule
    val fixture = BrokerFixture()

    /** Records every delivery and which ids took effect (first seen). */
    private class Receiver : InboxListener {
        private val deduplicator = BoundedDeduplicator()
        val deliveries = AtomicInteger()
        val accepted: MutableList<String> = Collections.synchronizedList(mutableListOf())

        override fun onInboxEvent(event: InboxEvent) {
            if (event !is InboxEvent.MessageReceived) throw AssertionError("unexpected $event")
            deliveries.incrementAndGet()
            if (deduplicator.firstSeen(event.message.id)) accepted += event.message.id
        }
    }

    @Test
    fun thousandMessages_brokerRestartsMidStreamWhileTheReceiverIsOffline_noneLostNoneDuplicated() = runBlocking {
        val count = 1_000
        val receiver = Receiver()
        val bobName = uniqueUser("bob")
        val bob = fixture.connected(bobName, receiver, device = "phone")
        val alice = fixture.connected(uniqueUser("alice"), { }, device = "laptop")

        val outbox = InMemoryOutbox()
        val retries = RetryPolicy(initialDelayMillis = 50, maxDelayMillis = 500)
        val sender = OutboxSender(outbox, alice, retries, Clock.SYSTEM, sendTimeoutMillis = 2_000)
        val messages = List(count) { ChatMessage.compose(alice.user, "message $it", icon = HapticIcon.KNOCK.takeIf { _ -> it % 10 == 0 }) }
        for (m in messages) outbox.enqueue(bobName, m)
        val sending = launch(Dispatchers.Default) { sender.run() }

        withTimeout(60_000) {
            // 1. The receiver goes offline after a quarter; the broker queues the rest for its session.
            while (receiver.accepted.size < count / 4) delay(1)
            bob.disconnect()
            // 2. Halfway through sending, the broker restarts: in-flight publishes fail and are retried, and
            //    what it queued for bob must come back from its store.
            while (outbox.pending().size > count / 2) delay(1)
            fixture.broker.restart()
            // 3. The sender reconnects by itself and drains the outbox.
            while (outbox.pending().isNotEmpty()) delay(10)
        }
        sending.cancelAndJoin()

        // 4. The receiver comes back (a new process on the same device): its session delivers the rest.
        fixture.connected(bobName, receiver, device = "phone")
        withTimeout(60_000) { while (receiver.accepted.size < count) delay(10) }

        assertEquals(count, receiver.accepted.size)
        assertEquals(messages.map { it.id }.toSet(), receiver.accepted.toSet())
        // Repeats may arrive (unacknowledged deliveries are redelivered); they took no effect.
        println("reliable delivery: $count messages, ${receiver.deliveries.get() - count} redelivered and dropped as duplicates")
    }
}

