package org.hapticon.messaging

import org.hapticon.testing.InMemoryOutbox
import kotlinx.coroutines.async
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import kotlinx.coroutines.yield
import org.junit.Assert.assertEquals
import org.junit.Test

class OutboxSenderTest {
    private val clock = FakeClock(100_000)
    private val outbox = InMemoryOutbox()
    private val messenger = RecordingMessenger()
    private val policy = RetryPolicy(initialDelayMillis = 1_000, maxDelayMillis = 8_000, jitter = 0.0)
    private val sender = OutboxSender(outbox, messenger, policy, clock, sendTimeoutMillis = 50)
    private val messages = (1..4).map { ChatMessage("00000000-0000-4000-8000-00000000000$it", "alice", it.toLong(), "m$it") }

    @Test
    fun sendDue_allAcknowledged_sendsInOrderAndEmptiesTheOutbox() = runBlocking {
        for (m in messages) sender.enqueue("bob", m)
        assertEquals(4, sender.sendDue())
        assertEquals(messages.map { "bob" to it }, messenger.sentMessages)
        // Acknowledged by the broker, kept until bob confirms: resent after the message's age (≈ 100 s here).
        assertEquals(messages.map { true to 100_000 + (100_000 - it.sentAtMillis) }, outbox.pending().map { it.awaitingReceipt to it.nextAttemptAtMillis })
        assertEquals(false, sender.confirm(Receipt(messages[0].id, "mallory", ReceiptState.DELIVERED, 1))) // not the recipient
        for (m in messages) assertEquals(true, sender.confirm(Receipt(m.id, "bob", ReceiptState.DELIVERED, 1)))
        assertEquals(emptyList<OutboxEntry>(), outbox.pending())
        assertEquals(false, sender.confirm(Receipt(messages[0].id, "bob", ReceiptState.READ, 2))) // already gone
    }

    @Test
    fun sendDue_noReceipt_resendsWithDoublingDelaysUpToTheCapUntilConfirmed() = runBlocking {
        val resender = OutboxSender(outbox, messenger, policy, clock, sendTimeoutMillis = 50, receiptTimeoutMillis = 30_000, maxResendDelayMillis = 200_000)
        val fresh = ChatMessage.compose("alice", "hi", clock = clock)
        resender.enqueue("bob", fresh)
        val delays = mutableListOf<Long>()
        repeat(6) {
            assertEquals(1, resender.sendDue())
            val next = outbox.nextAttemptAt()!!
            delays += next - clock.now
            clock.now = next - 1
            assertEquals(0, resender.sendDue()) // not before its time
            clock.now = next
        }
        // 30 s (the receipt timeout) while the message is young, then its age: doubling, capped at 200 s.
        assertEquals(listOf(30_000L, 30_000, 60_000, 120_000, 200_000, 200_000), delays)
        assertEquals(6, messenger.sentMessages.size)
        // A reconnection does not resend what awaits its receipt before its time.
        clock.now -= 1
        assertEquals(0, resender.sendDue(ignoreSchedule = true))
        assertEquals(true, resender.confirm(Receipt(fresh.id, "bob", ReceiptState.DELIVERED, 1)))
        clock.advance(1_000_000)
        assertEquals(0, resender.sendDue(ignoreSchedule = true))
        assertEquals(6, messenger.sentMessages.size)
    }

    @Test
    fun sendDue_failure_reschedulesThatEntryAndEndsThePass() = runBlocking {
        for (m in messages) sender.enqueue("bob", m)
        messenger.failWith = { if (it == messages[1]) MessagingException("not connected") else null }
        assertEquals(1, sender.sendDue())
        assertEquals(listOf(messages[0].id, messages[1].id), messenger.attempts)
        assertEquals(
            OutboxEntry("bob", messages[1], attempts = 1, nextAttemptAtMillis = 101_000, lastError = "not connected"),
            outbox.pending().single { it.message == messages[1] },
        )
        // The next pass, still at the same time, sends the two that were never tried and leaves the failed one.
        messenger.failWith = { null }
        assertEquals(2, sender.sendDue())
        assertEquals(listOf(messages[1].id), outbox.pending().filter { !it.awaitingReceipt }.map { it.message.id })
    }

    @Test
    fun sendDue_repeatedFailures_backOffExponentiallyUpToTheCap() = runBlocking {
        sender.enqueue("bob", messages[0])
        messenger.failWith = { MessagingException("broker down") }
        val schedule = mutableListOf<Long>()
        repeat(6) {
            clock.now = outbox.nextAttemptAt()!!
            assertEquals(0, sender.sendDue())
            schedule += outbox.nextAttemptAt()!! - clock.now
        }
        assertEquals(listOf(1_000L, 2_000, 4_000, 8_000, 8_000, 8_000), schedule)
        assertEquals(6, outbox.pending().single().attempts)
    }

    @Test
    fun sendDue_beforeTheScheduledRetry_leavesTheEntryAloneUnlessTheScheduleIsIgnored() = runBlocking {
        sender.enqueue("bob", messages[0])
        messenger.failWith = { MessagingException("broker down") }
        sender.sendDue()
        messenger.failWith = { null }
        clock.advance(999)
        assertEquals(0, sender.sendDue())
        assertEquals(1, messenger.attempts.size)
        assertEquals(1, sender.sendDue(ignoreSchedule = true))
        assertEquals(listOf("bob" to messages[0]), messenger.sentMessages)
    }

    @Test
    fun sendDue_acknowledgementNeverComes_timesOutAndCountsAFailure() = runBlocking {
        sender.enqueue("bob", messages[0])
        messenger.hangOn = { true }
        assertEquals(0, sender.sendDue())
        assertEquals("no acknowledgement within 50 ms", outbox.pending().single().lastError)
    }

    @Test
    fun sendDue_unexpectedException_isRecordedNotThrown() = runBlocking {
        sender.enqueue("bob", messages[0])
        messenger.failWith = { IllegalStateException("bug") }
        assertEquals(0, sender.sendDue())
        assertEquals("bug", outbox.pending().single().lastError)
    }

    @Test
    fun run_whileDisconnected_sendsNothingUntilConnectedThenEverything() = runBlocking {
        messenger.mutableState.value = ConnectionState.Connecting(lastFailure = null)
        for (m in messages) outbox.enqueue("bob", m)
        val running = async { sender.run() }
        repeat(10) { yield() }
        assertEquals(emptyList<String>(), messenger.attempts)
        messenger.mutableState.value = ConnectionState.Connected
        withTimeout(10_000) { while (outbox.pending().any { !it.awaitingReceipt }) yield() }
        assertEquals(messages.map { "bob" to it }, messenger.sentMessages)
        // Enqueued while running: the wake-up sends it without waiting for anything else.
        val late = ChatMessage(ID_1, "alice", 9, "late")
        sender.enqueue("carol", late)
        withTimeout(10_000) { while (outbox.pending().any { !it.awaitingReceipt }) yield() }
        assertEquals("carol" to late, messenger.sentMessages.last())
        running.cancel()
    }
}
