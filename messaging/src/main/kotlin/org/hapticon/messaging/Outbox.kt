package org.hapticon.messaging

/**
 * A message waiting to be sent, or sent and waiting for the receiver's delivered receipt.
 *
 * @property recipient the user whose inbox it goes to.
 * @property message the message itself.
 * @property attempts failed attempts so far.
 * @property nextAttemptAtMillis when it may be tried next (wall-clock ms; 0 = at once); for a message
 *   awaiting its receipt, when to send it again if none came.
 * @property lastError why the last attempt failed, or null before the first failure.
 * @property awaitingReceipt true once the broker acknowledged it: it stays until the receiver confirms it.
 */
public data class OutboxEntry(
    val recipient: String,
    val message: ChatMessage,
    val attempts: Int = 0,
    val nextAttemptAtMillis: Long = 0,
    val lastError: String? = null,
    val awaitingReceipt: Boolean = false,
)

/**
 * Messages composed but not yet confirmed by the receiver, so that a user can write while offline and
 * nothing is lost when the app, the connection or the broker dies. [OutboxSender] drains it.
 *
 * An entry lives from [enqueue] until the receiver's delivered (or read) receipt arrives ([markDelivered]),
 * not merely until the broker acknowledged it ([markSent]): a broker acknowledges before it has saved
 * (Mosquitto writes its store every `autosave_interval`, a second in the shipped configuration; a kill in between loses what it
 * acknowledged), so the end-to-end receipt is the only proof of delivery (the end-to-end argument, Saltzer,
 * Reed and Clark 1984). Until it comes the entry is sent again now and then, and the receiver drops the
 * repeats by id.
 *
 * Functions suspend because a real outbox is a database (the app backs this with Room); implementations
 * must be safe to call from several coroutines.
 */
public interface Outbox {
    /** Adds [message] for [recipient], due at once. Enqueuing an id already pending does nothing. */
    public suspend fun enqueue(recipient: String, message: ChatMessage)

    /**
     * Up to [limit] entries due at [nowMillis] (next attempt at or before it), in the order they were
     * enqueued: a message that failed once goes before later ones once it is due again.
     */
    public suspend fun due(nowMillis: Long, limit: Int): List<OutboxEntry>

    /** The earliest next-attempt time of any entry, or null when the outbox is empty. */
    public suspend fun nextAttemptAt(): Long?

    /**
     * The broker acknowledged [messageId]: keep the entry, now [OutboxEntry.awaitingReceipt], due again at
     * [resendAtMillis] unless [markDelivered] removes it first. Does nothing when there is no such entry.
     */
    public suspend fun markSent(messageId: String, resendAtMillis: Long)

    /**
     * The receiver [by] confirmed [messageId] with a receipt: removes the entry, when its recipient is [by]
     * (a receipt from anyone else confirms nothing). Returns whether it removed one.
     */
    public suspend fun markDelivered(messageId: String, by: String): Boolean

    /**
     * Records a failed attempt for [messageId]: one more attempt, [error], and the next try at
     * [nextAttemptAtMillis]. Does nothing when there is no such entry.
     */
    public suspend fun markFailed(messageId: String, error: String, nextAttemptAtMillis: Long)

    /** Every pending entry, in the order they were enqueued. */
    public suspend fun pending(): List<OutboxEntry>
}

/** An [Outbox] in memory: for the command-line chat and tests. Its content dies with the process. */
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
