package org.hapticon.messaging

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import java.util.concurrent.atomic.AtomicLong

/**
 * Drains an [Outbox] through a [Messenger]: sends what is due, reschedules failures by [retryPolicy], and
 * keeps what the broker acknowledged until the receiver's receipt confirms it ([confirm], which the
 * owner calls for every receipt that arrives). With a persistent outbox this is what makes offline
 * composing work, and what makes delivery survive a broker that loses acknowledged messages.
 *
 * An acknowledged message without a receipt is sent again after `max(receiptTimeoutMillis, its age)`,
 * capped at [maxResendDelayMillis]: the delays double as the message ages (30 s, 1 min, 2 min… up to an
 * hour by default), so an offline receiver's queue gets a handful of copies a day, not a flood. A
 * reconnection sends every never-acknowledged entry at once, but not the ones awaiting receipts.
 *
 * Retries and resends deliver a message more than once; receivers deduplicate by id and send the receipt
 * again for a repeat. Entries are sent one at a time, each awaiting its acknowledgement.
 */
public class OutboxSender(
    private val outbox: Outbox,
    private val messenger: Messenger,
    private val retryPolicy: RetryPolicy = RetryPolicy(),
    private val clock: Clock = Clock.SYSTEM,
    private val sendTimeoutMillis: Long = 10_000,
    private val receiptTimeoutMillis: Long = 30_000,
    private val maxResendDelayMillis: Long = 3_600_000,
) {
    init {
        require(sendTimeoutMillis >= 1) { "sendTimeoutMillis must be >= 1, was $sendTimeoutMillis" }
        require(receiptTimeoutMillis >= 1) { "receiptTimeoutMillis must be >= 1, was $receiptTimeoutMillis" }
        require(maxResendDelayMillis >= receiptTimeoutMillis) { "maxResendDelayMillis must be >= receiptTimeoutMillis, was $maxResendDelayMillis" }
    }

    /**
     * A [receipt] arrived: when it confirms a message of the outbox (its sender is the message's
     * recipient), that message is done and leaves the outbox. Returns whether it did.
     */
    public suspend fun confirm(receipt: Receipt): Boolean = outbox.markDelivered(receipt.messageId, receipt.from)

    private val wakeups = Channel<Unit>(Channel.CONFLATED)
    private val connections = AtomicLong()

    /** Puts [message] for [recipient] into the outbox and wakes [run]. Suspends while the outbox stores it. */
    public suspend fun enqueue(recipient: String, message: ChatMessage) {
        outbox.enqueue(recipient, message)
        wake()
    }

    /** Makes [run] look at the outbox now, for example after something was enqueued elsewhere. Never blocks. */
    public fun wake() {
        wakeups.trySend(Unit)
    }

    /**
     * One pass: sends every entry due at the clock's current time (with [ignoreSchedule] also every entry
     * the broker never acknowledged), oldest first, and returns how many the broker acknowledged. The first
     * failure ends the pass (the connection is probably gone; the rest would fail too): that entry is
     * rescheduled and counted as an attempt. Suspends while sending; does not throw except
     * [CancellationException].
     */
    public suspend fun sendDue(ignoreSchedule: Boolean = false): Int {
        var sent = 0
        if (ignoreSchedule) {
            val now = clock.nowMillis()
            for (entry in outbox.pending().filter { !it.awaitingReceipt || it.nextAttemptAtMillis <= now }) {
                if (!sendOne(entry)) return sent
                sent++
            }
        }
        while (true) {
            // Every entry sent is rescheduled into the future (resend or retry), so this loop ends.
            val batch = outbox.due(clock.nowMillis(), BATCH_SIZE)
            if (batch.isEmpty()) return sent
            for (entry in batch) {
                if (!sendOne(entry)) return sent
                sent++
            }
        }
    }

    /** Sends [entry] and records the outcome; returns whether the broker acknowledged it. */
    private suspend fun sendOne(entry: OutboxEntry): Boolean {
        val failure = attempt(entry)
        val now = clock.nowMillis()
        if (failure != null) {
            outbox.markFailed(entry.message.id, failure, retryPolicy.nextAttemptAt(now, entry.attempts + 1))
            return false
        }
        val age = now - entry.message.sentAtMillis
        outbox.markSent(entry.message.id, now + age.coerceIn(receiptTimeoutMillis, maxResendDelayMillis))
        return true
    }

    /**
     * Sends for as long as it runs, until cancelled: whenever the messenger is connected and an entry is
     * due, a [wake] arrives, or the connection comes back (then every pending entry goes at once: the
     * backoff was waiting for the broker, which is back). Suspends forever; cancel it to stop.
     */
    public suspend fun run(): Nothing = coroutineScope {
        launch {
            messenger.state.collect { state ->
                if (state == ConnectionState.Connected) {
                    connections.incrementAndGet()
                    wake()
                }
            }
        }
        var handledConnection = 0L
        while (true) {
            messenger.state.first { it == ConnectionState.Connected }
            val connection = connections.get()
            sendDue(ignoreSchedule = connection != handledConnection)
            handledConnection = connection
            val next = outbox.nextAttemptAt()
            if (next == null) {
                wakeups.receive()
            } else {
                val wait = next - clock.nowMillis()
                if (wait > 0) withTimeoutOrNull(wait) { wakeups.receive() }
            }
        }
        @Suppress("UNREACHABLE_CODE")
        throw IllegalStateException("unreachable")
    }

    /** Publishes [entry]; returns null when acknowledged, else why not. */
    private suspend fun attempt(entry: OutboxEntry): String? = try {
        val acknowledged = withTimeoutOrNull(sendTimeoutMillis) {
            messenger.send(entry.recipient, entry.message)
            true
        }
        if (acknowledged == true) null else "no acknowledgement within $sendTimeoutMillis ms"
    } catch (e: CancellationException) {
        throw e
    } catch (e: Exception) {
        // MessagingException normally; anything else must not end the sender either.
        e.message ?: e.javaClass.simpleName
    }

    private companion object {
        const val BATCH_SIZE = 64
    }
}
