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
