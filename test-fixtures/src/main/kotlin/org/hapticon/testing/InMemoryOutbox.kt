package org.hapticon.testing

import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Outbox
import org.hapticon.messaging.OutboxEntry
import org.hapticon.messaging.Topics

/** An [Outbox] in memory, for tests: its content dies with the process (the app keeps its outbox in Room, `hapticon chat` in a file). */
public class InMemoryOutbox : Outbox {
    private val entries = LinkedHashMap<String, OutboxEntry>() // insertion order = enqueue order

    override suspend fun enqueue(recipient: String, message: ChatMessage) {
        Topics.requireUserName(recipient)
        synchronized(entries) { entries.putIfAbsent(message.id, OutboxEntry(recipient, message)) }
    }

    override suspend fun due(nowMillis: Long, limit: Int): List<OutboxEntry> {
        require(limit >= 0) { "limit must be >= 0, was $limit" }
        return synchronized(entries) { entries.values.asSequence().filter { it.nextAttemptAtMillis <= nowMillis }.take(limit).toList() }
    }

    override suspend fun nextAttemptAt(): Long? = synchronized(entries) { entries.values.minOfOrNull { it.nextAttemptAtMillis } }

    override suspend fun markSent(messageId: String, resendAtMillis: Long) {
        synchronized(entries) {
            entries.computeIfPresent(messageId) { _, entry -> entry.copy(awaitingReceipt = true, nextAttemptAtMillis = resendAtMillis) }
        }
    }

    override suspend fun markDelivered(messageId: String, by: String): Boolean = synchronized(entries) {
        if (entries[messageId]?.recipient == by) entries.remove(messageId) != null else false
    }

    override suspend fun markFailed(messageId: String, error: String, nextAttemptAtMillis: Long) {
        synchronized(entries) {
            entries.computeIfPresent(messageId) { _, entry ->
                entry.copy(attempts = entry.attempts + 1, nextAttemptAtMillis = nextAttemptAtMillis, lastError = error)
            }
        }
    }

    override suspend fun pending(): List<OutboxEntry> = synchronized(entries) { entries.values.toList() }
}
