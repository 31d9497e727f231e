package org.hapticon.app.sync

import kotlinx.coroutines.awaitCancellation
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.update
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.HandPose
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.InboxListener
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.Messenger
import org.hapticon.messaging.MessagingException
import org.hapticon.messaging.Receipt

/** A [Messenger] in memory: records what is sent (as the JSON the codec makes) and delivers what a test hands it. */
class TestMessenger(override val user: String) : Messenger {
    private val connection = MutableStateFlow<ConnectionState>(ConnectionState.Disconnected)
    override val state: StateFlow<ConnectionState> = connection

    /** Published messages: recipient and the JSON payload. */
    val sentMessages = MutableStateFlow<List<Pair<String, String>>>(emptyList())
    val sentReceipts = MutableStateFlow<List<Pair<String, Receipt>>>(emptyList())
    val published = MutableStateFlow<List<Capabilities>>(emptyList())

    /** When true, sending fails as an unreachable broker would. */
    @Volatile
    var failing = false

    @Volatile
    private var listener: InboxListener? = null

    override suspend fun connect(listener: InboxListener) {
        this.listener = listener
        connection.value = ConnectionState.Connected
        try {
            awaitCancellation()
        } finally {
            connection.value = ConnectionState.Disconnected
        }
    }

    /** Changes the connection as a dropped or restored link would, without ending [connect]. */
    fun setConnection(state: ConnectionState) {
        connection.value = state
    }

    /** How often [reconnectNow] was called. */
    @Volatile
    var nudges = 0

    override fun reconnectNow() {
        nudges++
    }

    /** Whether the broker answers [ping] (false: a connection that died unnoticed); [pings] counts the round trips. */
    @Volatile
    var answersPing = true

    @Volatile
    var pings = 0

    override suspend fun ping(timeoutMillis: Long): Boolean {
        pings++
        return connection.value == ConnectionState.Connected && answersPing
    }

    override suspend fun disconnect() {
        connection.value = ConnectionState.Disconnected
    }

    override suspend fun send(recipient: String, message: ChatMessage) {
        if (failing) throw MessagingException("broker unreachable")
        sentMessages.update { it + (recipient to MessageCodec.encode(message).decodeToString()) }
    }

    override suspend fun send(recipient: String, receipt: Receipt) {
        if (failing) throw MessagingException("broker unreachable")
        sentReceipts.update { it + (recipient to receipt) }
    }

    val sentPoses = MutableStateFlow<List<Pair<String, HandPose>>>(emptyList())

    override suspend fun send(recipient: String, pose: HandPose) {
        if (failing) throw MessagingException("broker unreachable")
        sentPoses.update { it + (recipient to pose) }
    }

    override suspend fun publishCapabilities(capabilities: Capabilities) {
        published.update { it + capabilities }
    }

    /** Delivers [event] as the broker would, on the caller's thread. */
    fun deliver(event: InboxEvent) = checkNotNull(listener) { "not connected" }.onInboxEvent(event)

    /** Delivers a raw [payload] through the codec, as MqttMessenger does. */
    fun deliverRaw(topic: String, payload: ByteArray) = deliver(
        when (val decoded = MessageCodec.decodeInbox(payload)) {
            is org.hapticon.messaging.Decoded.Accepted -> when (val value = decoded.value) {
                is ChatMessage -> InboxEvent.MessageReceived(value)
                is Receipt -> InboxEvent.ReceiptReceived(value)
                is HandPose -> InboxEvent.HandPoseReceived(value)
            }
            is org.hapticon.messaging.Decoded.Rejected -> InboxEvent.Rejected(topic, decoded)
        },
    )
}
