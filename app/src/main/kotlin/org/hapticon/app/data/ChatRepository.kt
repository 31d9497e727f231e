package org.hapticon.app.data

import androidx.room.withTransaction
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.map
import org.hapticon.app.data.database.ConversationEntity
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.data.database.MessageEntity
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.OutboxEntity
import org.hapticon.app.data.database.PendingReceiptEntity
import org.hapticon.app.data.database.SeenMessageEntity
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.data.database.asExternalModel
import org.hapticon.app.data.database.patternFromJson
import org.hapticon.app.data.database.patternToJson
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.Outbox
import org.hapticon.messaging.OutboxEntry
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState

/**
 * Conversations and messages, offline first: the UI reads Room, sending writes the message and its
 * outbox entry to Room in one transaction before any network call, and the background sync
 * ([org.hapticon.app.sync.ChatSync]) moves them over the network and records what comes back.
 */
interface ChatRepository {
    /** Every conversation with its latest message, newest first. */
    fun conversations(): Flow<List<ConversationSummary>>

    /** The messages with [peer], oldest first. */
    fun messages(peer: String): Flow<List<StoredMessage>>

    /** Creates the conversation with [peer] unless it exists. */
    suspend fun startConversation(peer: String)

    /**
     * Stores a new own message from [sender] to [peer] and queues it for sending. Throws
     * [org.hapticon.messaging.InvalidMessageException] when the message is not valid (e.g. empty).
     */
    suspend fun send(
        sender: String,
        peer: String,
        text: String,
        sticker: String? = null,
        icon: HapticIcon? = null,
        pattern: HapticPattern? = null,
    ): StoredMessage

    /**
     * Stores a received [message] unless its sender's id was seen before, even in a conversation deleted since;
     * returns true when it is new (first delivery), false for a repeat or a replay.
     */
    suspend fun receive(message: ChatMessage): Boolean

    /** Records a receipt for an own message; states only move forward (a late DELIVERED never undoes READ). */
    suspend fun applyReceipt(receipt: Receipt)

    /** Marks the received messages of [peer] as read at [nowMillis]; returns those that were unread. */
    suspend fun markRead(peer: String, nowMillis: Long): List<StoredMessage>

    /** The message with [id], or null when there is none. */
    suspend fun message(id: String): StoredMessage?

    /** Every stored message, by conversation then time (the export). */
    suspend fun allMessages(): List<StoredMessage>

    /**
     * Makes a failed or waiting own message due for sending now (the user tapped retry): the same row, sent with the
     * same id. A failed one shows as sending again until the broker acknowledges it or it fails anew.
     */
    suspend fun retryNow(messageId: String)

    /**
     * Deletes the conversation with [peer], its messages and whatever of it is still in the outbox. The ids of its
     * received messages stay seen: a replay of one of them is not shown as new.
     */
    suspend fun deleteConversation(peer: String)

    /** Keeps [receipt] for [peer] until [receiptSent]: it could not be sent now. */
    suspend fun queueReceipt(peer: String, receipt: Receipt)

    /** The receipts still owed, oldest first. */
    suspend fun pendingReceipts(): List<PendingReceipt>

    /** Forgets a queued receipt once it went out. */
    suspend fun receiptSent(receipt: Receipt)
}

/** A receipt owed to [peer]. */
data class PendingReceipt(val peer: String, val receipt: Receipt)

/** [ChatRepository] on Room. Also the [Outbox] that the sync's [org.hapticon.messaging.OutboxSender] drains. */
class OfflineFirstChatRepository(
    private val db: HapticonDatabase,
    private val clock: Clock = Clock.SYSTEM,
    /** After this many failed attempts an own message shows as failed (it is still retried). */
    private val failedAfterAttempts: Int = 3,
) : ChatRepository, Outbox {
    private val conversations = db.conversationDao()
    private val messages = db.messageDao()
    private val outbox = db.outboxDao()
    private val receipts = db.pendingReceiptDao()
    private val seen = db.seenMessageDao()

    override fun conversations(): Flow<List<ConversationSummary>> = conversations.conversationSummaries()

    override fun messages(peer: String): Flow<List<StoredMessage>> =
        messages.messages(peer).map { rows -> rows.map { it.asExternalModel() } }

    override suspend fun startConversation(peer: String) {
        conversations.insertOrIgnore(ConversationEntity(peer, clock.nowMillis()))
    }

    override suspend fun send(sender: String, peer: String, text: String, sticker: String?, icon: HapticIcon?, pattern: HapticPattern?): StoredMessage {
        val message = ChatMessage.compose(sender, text, sticker, icon, clock, pattern)
        enqueue(peer, message)
        return messages.message(message.id)!!.asExternalModel()
    }

    override suspend fun receive(message: ChatMessage): Boolean = db.withTransaction {
        // The seen id decides, not the message row: "Delete conversation" removes rows but must not reopen replays.
        if (seen.insertOrIgnore(SeenMessageEntity(message.sender, message.id, clock.nowMillis())) == -1L) return@withTransaction false
        val inserted = messages.insertOrIgnore(message.asEntity(conversation = message.sender, outgoing = false, state = MessageState.RECEIVED))
        if (inserted != -1L) conversations.insertOrIgnore(ConversationEntity(message.sender, clock.nowMillis()))
        inserted != -1L
    }

    override suspend fun applyReceipt(receipt: Receipt) {
        db.withTransaction {
            val row = messages.message(receipt.messageId) ?: return@withTransaction
            // Only the peer the message went to may acknowledge it.
            if (!row.outgoing || row.conversation != receipt.from) return@withTransaction
            when (receipt.state) {
                ReceiptState.DELIVERED -> if (row.state in FORWARD_TO_DELIVERED) messages.updateState(row.id, MessageState.DELIVERED.name)
                ReceiptState.READ -> if (row.state != MessageState.READ.name && row.state != MessageState.FELT.name) {
                    messages.updateStateAndReadAt(row.id, MessageState.READ.name, receipt.atMillis)
                }
                // Felt implies read: the read time is kept when known, else the felt time stands in.
                ReceiptState.FELT -> if (row.state != MessageState.FELT.name) {
                    messages.updateStateAndReadAt(row.id, MessageState.FELT.name, row.readAtMillis ?: receipt.atMillis)
                }
            }
        }
    }

    override suspend fun markRead(peer: String, nowMillis: Long): List<StoredMessage> = db.withTransaction {
        val unread = messages.unread(peer)
        for (row in unread) messages.updateStateAndReadAt(row.id, MessageState.READ.name, nowMillis)
        unread.map { it.asExternalModel() }
    }

    override suspend fun message(id: String): StoredMessage? = messages.message(id)?.asExternalModel()

    override suspend fun allMessages(): List<StoredMessage> = messages.all().map { it.asExternalModel() }

    override suspend fun retryNow(messageId: String) {
        db.withTransaction {
            outbox.dueNow(messageId, clock.nowMillis())
            val row = messages.message(messageId) ?: return@withTransaction
            if (row.outgoing && row.state == MessageState.FAILED.name && outbox.entry(messageId) != null) {
                messages.updateState(messageId, MessageState.SENDING.name)
            }
        }
    }

    override suspend fun deleteConversation(peer: String) {
        db.withTransaction {
            outbox.deleteFor(peer)
            messages.deleteConversationMessages(peer)
            conversations.deleteConversation(peer)
        }
    }

    override suspend fun queueReceipt(peer: String, receipt: Receipt) {
        receipts.upsert(PendingReceiptEntity(receipt.messageId, receipt.state.wireName, peer, receipt.from, receipt.atMillis))
    }

    override suspend fun pendingReceipts(): List<PendingReceipt> = receipts.pending().mapNotNull { row ->
        val state = ReceiptState.entries.firstOrNull { it.wireName == row.state } ?: return@mapNotNull null
        PendingReceipt(row.peer, Receipt(row.messageId, row.fromUser, state, row.atMillis))
    }

    override suspend fun receiptSent(receipt: Receipt) {
        receipts.delete(receipt.messageId, receipt.state.wireName)
    }

    // Outbox, for OutboxSender.

    override suspend fun enqueue(recipient: String, message: ChatMessage) {
        db.withTransaction {
            conversations.insertOrIgnore(ConversationEntity(recipient, clock.nowMillis()))
            messages.insertOrIgnore(message.asEntity(conversation = recipient, outgoing = true, state = MessageState.SENDING))
            outbox.insertOrIgnore(OutboxEntity(message.id, recipient, enqueuedAtMillis = clock.nowMillis()))
        }
    }

    override suspend fun due(nowMillis: Long, limit: Int): List<OutboxEntry> = outbox.due(nowMillis, limit).mapNotNull { it.asEntry() }

    override suspend fun nextAttemptAt(): Long? = outbox.nextAttemptAt()

    // The entry stays until the receiver's delivered receipt (markDelivered): the broker's acknowledgement
    // is not proof of delivery (Outbox). The message shows SENT meanwhile.
    override suspend fun markSent(messageId: String, resendAtMillis: Long) {
        db.withTransaction {
            outbox.reschedule(messageId, resendAtMillis)
            val row = messages.message(messageId) ?: return@withTransaction
            // A receipt can overtake the acknowledgement; never move a message backwards.
            if (row.state == MessageState.SENDING.name || row.state == MessageState.FAILED.name) {
                messages.updateState(messageId, MessageState.SENT.name)
            }
        }
    }

    override suspend fun markDelivered(messageId: String, by: String): Boolean = db.withTransaction {
        // Only the recipient's receipt confirms (the receipt's topic proves who sent it).
        if (outbox.entry(messageId)?.recipient != by) return@withTransaction false
        outbox.deleteEntry(messageId)
        true
    }

    override suspend fun markFailed(messageId: String, error: String, nextAttemptAtMillis: Long) {
        db.withTransaction {
            outbox.markFailed(messageId, error, nextAttemptAtMillis)
            val entry = outbox.entry(messageId) ?: return@withTransaction
            // A resend that fails does not undo SENT: the broker acknowledged an earlier copy.
            val row = messages.message(messageId) ?: return@withTransaction
            if (entry.attempts >= failedAfterAttempts && row.state == MessageState.SENDING.name) {
                messages.updateState(messageId, MessageState.FAILED.name)
            }
        }
    }

    override suspend fun pending(): List<OutboxEntry> = outbox.pending().mapNotNull { it.asEntry() }

    private suspend fun OutboxEntity.asEntry(): OutboxEntry? {
        val row = messages.message(messageId) ?: return null
        val acknowledged = row.state != MessageState.SENDING.name && row.state != MessageState.FAILED.name
        return OutboxEntry(recipient, row.asChatMessage(), attempts, nextAttemptAtMillis, lastError, awaitingReceipt = acknowledged)
    }

    private companion object {
        val FORWARD_TO_DELIVERED = setOf(MessageState.SENDING.name, MessageState.SENT.name, MessageState.FAILED.name)
    }
}

/** The row for [this] message; positional, in [MessageEntity]'s column order, as `MessageEntity.asChatMessage` reads it back. */
internal fun ChatMessage.asEntity(conversation: String, outgoing: Boolean, state: MessageState) = MessageEntity(
    id, conversation, sender, sentAtMillis, text, sticker, icon?.let { IconJson.encode(it) }, outgoing, state.name,
    patternJson = pattern?.let(::patternToJson),
)

internal fun MessageEntity.asChatMessage(): ChatMessage =
    ChatMessage(id, sender, sentAtMillis, text, sticker, iconJson?.let { IconJson.decode(it) }, patternJson?.let(::patternFromJson))
