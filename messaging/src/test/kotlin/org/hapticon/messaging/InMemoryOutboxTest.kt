package org.hapticon.messaging

import org.hapticon.testing.InMemoryOutbox
import kotlinx.coroutines.runBlocking
import org.junit.Assert.assertEquals
import org.junit.Test

class InMemoryOutboxTest {
    private val outbox = InMemoryOutbox()
    private val first = ChatMessage(ID_1, "alice", 1, "first")
    private val second = ChatMessage(ID_2, "alice", 2, "second")

    @Test
    fun enqueue_sameIdTwice_keepsOneEntry() = runBlocking {
        outbox.enqueue("bob", first)
        outbox.enqueue("bob", first.copy(text = "changed"))
        assertEquals(listOf(OutboxEntry("bob", first)), outbox.pending())
    }

    @Test
    fun due_entriesScheduledLater_areLeftOutUntilTheirTimeThenKeepTheirPlace() = runBlocking {
        outbox.enqueue("bob", first)
        outbox.enqueue("carol", second)
        outbox.markFailed(ID_1, "offline", nextAttemptAtMillis = 5_000)
        assertEquals(listOf(OutboxEntry("carol", second)), outbox.due(nowMillis = 4_999, limit = 10))
        assertEquals(
            listOf(OutboxEntry("bob", first, attempts = 1, nextAttemptAtMillis = 5_000, lastError = "offline"), OutboxEntry("carol", second)),
            outbox.due(nowMillis = 5_000, limit = 10),
        )
        assertEquals(0L, outbox.nextAttemptAt())
    }

    @Test
    fun due_manyEntries_keepTheEnqueueOrderAndTheLimit() = runBlocking {
        val ids = (0 until 5).map { "00000000-0000-4000-8000-00000000000$it" }
        for (id in ids) outbox.enqueue("bob", ChatMessage(id, "alice", 1, id))
        assertEquals(ids.take(3), outbox.due(0, limit = 3).map { it.message.id })
    }

    @Test
    fun markSentKeepsTheEntryUntilMarkDelivered_markFailedCountsAttempts() = runBlocking {
        outbox.enqueue("bob", first)
        outbox.enqueue("bob", second)
        outbox.markFailed(ID_2, "timeout", 10)
        outbox.markFailed(ID_2, "refused", 30)
        outbox.markSent(ID_1, resendAtMillis = 40)
        outbox.markSent("unknown", 1)
        outbox.markFailed("unknown", "x", 1)
        assertEquals(
            listOf(
                OutboxEntry("bob", first, nextAttemptAtMillis = 40, awaitingReceipt = true),
                OutboxEntry("bob", second, attempts = 2, nextAttemptAtMillis = 30, lastError = "refused"),
            ),
            outbox.pending(),
        )
        assertEquals(30L, outbox.nextAttemptAt())
        assertEquals(false, outbox.markDelivered(ID_1, by = "carol"))
        assertEquals(true, outbox.markDelivered(ID_1, by = "bob"))
        assertEquals(true, outbox.markDelivered(ID_2, by = "bob"))
        assertEquals(false, outbox.markDelivered(ID_2, by = "bob"))
        assertEquals(null, outbox.nextAttemptAt())
    }
}
