package org.hapticon.messaging

import kotlinx.coroutines.flow.StateFlow

/**
 * Sends and receives chat messages, receipts and capabilities for one user on one device.
 *
 * Delivery is at least once: the broker acknowledges what it has, keeps what an offline receiver has not
 * yet taken, and redelivers what was not acknowledged. A message can therefore arrive twice; receivers
 * make it take effect once with a [Deduplicator]. Senders that must survive going offline put messages
 * into an [Outbox] and let an [OutboxSender] call [send].
 */
public interface Messenger {
    /** The user this messenger sends as and receives for. */
    public val user: String

    /** The connection, as it changes. */
    public val state: StateFlow<ConnectionState>

    /**
     * Connects and stays connected: suspends until the first connection is established and the inbox
     * subscribed, retrying while the broker is unreachable; afterwards reconnects by itself whenever the
     * connection drops, until [disconnect].
     *
     * [listener] receives everything that arrives, from the first moment: a persistent session delivers
     * the messages queued while offline right after connecting. Throws [MessagingException] when the
     * broker refuses this client for good (bad credentials, subscription denied), [IllegalStateException]
     * when called twice. Cancelling the call disconnects.
     */
    public suspend fun connect(listener: InboxListener)

    /**
     * Disconnects cleanly; the broker keeps the session and queues messages until the next [connect]
     * (of a new messenger for the same user and device). Suspends until done; does not throw.
     */
    public suspend fun disconnect()

    /**
     * Ends the wait before the next reconnection attempt now: the network came back (Android's
     * connectivity callback says so), so the backoff that protects a down broker from a reconnecting
     * crowd would only keep the user unreachable. Does nothing while connected, connecting or after
     * [disconnect]. Returns at once; the attempt runs in the background. The default does nothing, for
     * messengers that have no waiting attempt to cut short.
     */
    public fun reconnectNow() {}

    /**
     * Sends one round trip to the broker now and suspends until it is answered: true when it was within
     * [timeoutMillis], false when not connected or no answer came (the connection is dead though not yet
     * noticed). For a phone that wakes from sleep only now and then: the client's own keep-alive timer counts
     * only awake time, so the broker would otherwise hear nothing. Does not throw. The default answers from
     * [state], for messengers without a round trip of their own.
     */
    public suspend fun ping(timeoutMillis: Long): Boolean = state.value == ConnectionState.Connected

    /**
     * Publishes [message] into [recipient]'s inbox and suspends until the broker has acknowledged it
     * (PUBACK). Throws [MessagingException] when not connected or the publish fails; the message may or may
     * not have reached the broker then, which is why receivers deduplicate. Throws
     * [IllegalArgumentException] when [recipient] is not a valid user name.
     */
    public suspend fun send(recipient: String, message: ChatMessage)

    /** Publishes [receipt] into [recipient]'s inbox (the original sender's), like [send]. Throws as [send] does. */
    public suspend fun send(recipient: String, receipt: Receipt)

    /**
     * Publishes [pose] into [recipient]'s inbox with QoS 0 (at most once, no acknowledgement): a live
     * stream where the next sample replaces a lost one. Throws [MessagingException] when
     * not connected, [IllegalArgumentException] when [recipient] is not a valid user name.
     */
    public suspend fun send(recipient: String, pose: HandPose)

    /**
     * Publishes this device's [capabilities] as the retained message of [user], replacing the previous one.
     * Throws [MessagingException] as [send] does, [IllegalArgumentException] when they describe another user.
     */
    public suspend fun publishCapabilities(capabilities: Capabilities)
}

/** The connection of a [Messenger]. */
public sealed interface ConnectionState {
    /** Not connected and not trying: before [Messenger.connect] or after [Messenger.disconnect]. */
    public data object Disconnected : ConnectionState

    /** Trying to connect, for the first time or again; [lastFailure] says why the last attempt or connection ended. */
    public data class Connecting(val lastFailure: String?) : ConnectionState

    /** Connected and subscribed: messages flow. */
    public data object Connected : ConnectionState

    /** Given up for good: the broker refused this client. [reason] says why. */
    public data class Failed(val reason: String) : ConnectionState
}

/** Receives what arrives for a [Messenger]'s user. */
public fun interface InboxListener {
    /**
     * Handles one [event]. Called on the messenger's delivery thread, one event at a time, in arrival
     * order; it may block (to store a message, say). The message is acknowledged to the broker after this
     * returns, so a crash before then means it is delivered again. Must not throw; an exception is logged
     * and the message acknowledged anyway, so that one bad message cannot stall the inbox.
     */
    public fun onInboxEvent(event: InboxEvent)
}

/** Something that arrived for the user. */
public sealed interface InboxEvent {
    /** A chat message; possibly a repeat of one already received. */
    public data class MessageReceived(val message: ChatMessage) : InboxEvent

    /** A receipt for a message this user sent. */
    public data class ReceiptReceived(val receipt: Receipt) : InboxEvent

    /** A tele-handshake partner's hand. */
    public data class HandPoseReceived(val pose: HandPose) : InboxEvent

    /**
     * A user's capabilities. [retained] is the broker's word that it sent the stored copy because this client just
     * subscribed (MQTT 3.1.1 §3.3.1.3: RETAIN 1 "as a result of a new subscription", 0 for a message published while
     * subscribed). Every client publishes its own on every connection, so the retained ones are a directory of the
     * users who ever connected; the copy of this user's own publish arrives with [retained] false after them.
     */
    public data class CapabilitiesReceived(val capabilities: Capabilities, val retained: Boolean = false) : InboxEvent

    /** A payload that was refused, for the listener to log or count; it has no other effect. */
    public data class Rejected(val topic: String, val rejection: Decoded.Rejected) : InboxEvent
}

/** Sending or connecting failed. [message] says why. */
public class MessagingException(message: String, cause: Throwable? = null) : Exception(message, cause)
