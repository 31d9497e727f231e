package org.hapticon.messaging

import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import java.util.concurrent.LinkedBlockingQueue
import java.util.concurrent.TimeUnit

/** A clock that moves only when told. */
class FakeClock(var now: Long = 0) : Clock {
    override fun nowMillis(): Long = now

    fun advance(millis: Long) {
        now += millis
    }
}

/** A [kotlin.random.Random] whose nextDouble is always [value]: makes jitter exact. */
class FixedRandom(private val value: Double) : kotlin.random.Random() {
    override fun nextBits(bitCount: Int): Int = 0
    override fun nextDouble(): Double = value
}

/**
 * A [Messenger] that records what is sent and fails the sends that [failWith] chooses; it never touches a
 * network. State is set by the test.
 */
class RecordingMessenger(override val user: String = "alice") : Messenger {
    val mutableState = MutableStateFlow<ConnectionState>(ConnectionState.Connected)
    override val state: StateFlow<ConnectionState> = mutableState

    val sentMessages = mutableListOf<Pair<String, ChatMessage>>()
    val sentReceipts = mutableListOf<Pair<String, Receipt>>()
    val attempts = mutableListOf<String>()

    /** Returns an exception to throw for a send of [ChatMessage], or null to succeed. */
    var failWith: (ChatMessage) -> Exception? = { null }

    /** Suspends forever on the sends it returns true for: an acknowledgement that never comes. */
    var hangOn: (ChatMessage) -> Boolean = { false }

    override suspend fun connect(listener: InboxListener) = Unit
    override suspend fun disconnect() = Unit

    override suspend fun send(recipient: String, message: ChatMessage) {
        attempts += message.id
        if (hangOn(message)) kotlinx.coroutines.awaitCancellation()
        failWith(message)?.let { throw it }
        sentMessages += recipient to message
    }

    override suspend fun send(recipient: String, receipt: Receipt) {
        sentReceipts += recipient to receipt
    }

    override suspend fun send(recipient: String, pose: HandPose) {
        sentPoses += recipient to pose
    }

    val sentPoses = mutableListOf<Pair<String, HandPose>>()

    override suspend fun publishCapabilities(capabilities: Capabilities) = Unit
}

/** Collects inbox events for assertions; a test waits for what it expects with [awaitEvents]. */
class CollectingListener : InboxListener {
    private val queue = LinkedBlockingQueue<InboxEvent>()
    val received = mutableListOf<InboxEvent>()

    override fun onInboxEvent(event: InboxEvent) {
        queue.put(event)
    }

    /** The next [count] events; fails when they do not arrive within a generous deadline (a hang, not a measurement). */
    fun awaitEvents(count: Int): List<InboxEvent> = List(count) {
        (queue.poll(WAIT_SECONDS, TimeUnit.SECONDS) ?: throw AssertionError("event ${it + 1} of $count did not arrive; got $received"))
            .also { event -> received += event }
    }

    /** The next event. */
    fun awaitEvent(): InboxEvent = awaitEvents(1).single()

    companion object {
        const val WAIT_SECONDS = 20L
    }
}

const val ID_1 = "3f1c2b9a-8d4e-4f6a-9b2c-1d2e3f4a5b6c"
const val ID_2 = "00000000-0000-4000-8000-000000000002"
const val NEW_YEAR_2026 = 1_767_225_600_000L
