package org.hapticon.messaging

import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.channels.Channel
import kotlinx.coroutines.coroutineScope
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.launch
import kotlinx.coroutines.withTimeoutOrNull
import java.util.concurrent.atomic.AtomicLong

/**
 * Drains an [Outbox] through a [Messenger]: sends what is due, removes what the broker acknowledged, and
 * reschedules failures by [retryPolicy]. With a persistent outbox this is what makes offline composing
 * work: messages wait in the outbox and flow when the broker is reachable again.
 *
 * Retries can deliver a message twice (an acknowledgement lost with the connection); receivers
 * deduplicate by id. Entries are sent one at a time, each awaiting its acknowledgement.
 */
public class OutboxSender(
    private val outbox: Outbox,
    private val messenger: Messenger,
    private val retryPolicy: RetryPolicy = RetryPolicy(),
    private val clock: Clock = Clock.SYSTEM,
    private val sendTimeoutMillis: Long = 10_000,
) {
    init {
        require(sendTimeoutMillis >= 1) { "sendTimeoutMillis must be >= 1, was $sendTimeoutMillis" }
    }

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
     * One pass: sends every entry due at the clock's current time (every pending entry when [ignoreSchedule]),
     * oldest first, and returns how many the broker acknowledged. The first failure ends the pass (the
     * connection is probably gone; the rest would fail too): that entry is rescheduled and counted as an
     * attempt. Suspends while sending; does not throw except [CancellationException].
     */
    public suspend fun sendDue(ignoreSchedule: Boolean = false): Int {
        var sent = 0
        while (true) {
            val batch = outbox.due(if (ignoreSchedule) Long.MAX_VALUE else clock.nowMillis(), BATCH_SIZE)
            if (batch.isEmpty()) return sent
            for (entry in batch) {
                val failure = attempt(entry)
                if (failure != null) {
                    val attempts = entry.attempts + 1
                    outbox.markFailed(entry.message.id, failure, retryPolicy.nextAttemptAt(clock.nowMillis(), attempts))
                    return sent
                }
                outbox.markSent(entry.message.id)
                sent++
            }
        }
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

    /** Sends [entry]; returns null when acknowledged, else why not. */
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
