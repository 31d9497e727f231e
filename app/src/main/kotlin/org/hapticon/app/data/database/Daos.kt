package org.hapticon.app.data.database

import androidx.room.Dao
import androidx.room.Insert
import androidx.room.OnConflictStrategy
import androidx.room.Query
import androidx.room.Upsert
import kotlinx.coroutines.flow.Flow

/** A conversation with its latest message, for the conversation list. */
data class ConversationSummary(
    val peer: String,
    val lastText: String?,
    val lastAtMillis: Long?,
    val unread: Int,
    /** The latest message's icon (JSON), for the preview's glyph and name; null without one. */
    val lastIconJson: String? = null,
    /** Whether the latest message is the user's own ("You: …"). */
    val lastOutgoing: Boolean = false,
)

/** Conversations; the list reads their latest message and unread count in one query. */
@Dao
interface ConversationDao {
    @Query(
        """
        SELECT c.peer AS peer,
          (SELECT m.text FROM messages m WHERE m.conversation = c.peer ORDER BY m.sent_at DESC LIMIT 1) AS lastText,
          (SELECT MAX(m.sent_at) FROM messages m WHERE m.conversation = c.peer) AS lastAtMillis,
          (SELECT m.icon_json FROM messages m WHERE m.conversation = c.peer ORDER BY m.sent_at DESC LIMIT 1) AS lastIconJson,
          COALESCE((SELECT m.outgoing FROM messages m WHERE m.conversation = c.peer ORDER BY m.sent_at DESC LIMIT 1), 0) AS lastOutgoing,
          (SELECT COUNT(*) FROM messages m WHERE m.conversation = c.peer AND m.outgoing = 0 AND m.state = 'RECEIVED') AS unread
        FROM conversations c
        ORDER BY COALESCE(lastAtMillis, c.created_at) DESC
        """,
    )
    fun conversationSummaries(): Flow<List<ConversationSummary>>

    /** Creates the conversation unless it exists. */
    @Insert(onConflict = OnConflictStrategy.IGNORE)
    suspend fun insertOrIgnore(conversation: ConversationEntity)

    @Query("DELETE FROM conversations WHERE peer = :peer")
    suspend fun deleteConversation(peer: String)
}

/** Messages; inserts ignore a known id, which makes repeated deliveries take effect once. */
@Dao
interface MessageDao {
    @Query("SELECT * FROM messages WHERE conversation = :peer ORDER BY sent_at, rowid")
    fun messages(peer: String): Flow<List<MessageEntity>>

    @Query("SELECT * FROM messages WHERE id = :id")
    suspend fun message(id: String): MessageEntity?

    /** Inserts unless a message with this id exists; returns the row id, or -1 when it did (a repeat). */
    @Insert(onConflict = OnConflictStrategy.IGNORE)
    suspend fun insertOrIgnore(message: MessageEntity): Long

    @Upsert
    suspend fun upsertMessage(message: MessageEntity)

    @Query("UPDATE messages SET state = :state WHERE id = :id")
    suspend fun updateState(id: String, state: String)

    @Query("UPDATE messages SET state = :state, read_at = :readAt WHERE id = :id")
    suspend fun updateStateAndReadAt(id: String, state: String, readAt: Long?)

    /** Received messages of [peer] not yet marked read. */
    @Query("SELECT * FROM messages WHERE conversation = :peer AND outgoing = 0 AND state = 'RECEIVED' ORDER BY sent_at")
    suspend fun unread(peer: String): List<MessageEntity>

    @Query("DELETE FROM messages WHERE id = :id")
    suspend fun deleteMessage(id: String)

    @Query("SELECT * FROM messages ORDER BY conversation, sent_at, rowid")
    suspend fun all(): List<MessageEntity>

    @Query("DELETE FROM messages WHERE conversation = :peer")
    suspend fun deleteConversationMessages(peer: String)
}

/** The ids of received messages, kept when their conversation is deleted ([SeenMessageEntity]). */
@Dao
interface SeenMessageDao {
    /** Records the id unless [peer] sent it before; returns the row id, or -1 when it was seen already (a repeat or a replay). */
    @Insert(onConflict = OnConflictStrategy.IGNORE)
    suspend fun insertOrIgnore(seen: SeenMessageEntity): Long

    @Query("SELECT * FROM seen_messages WHERE peer = :peer ORDER BY seen_at, rowid")
    suspend fun seenFrom(peer: String): List<SeenMessageEntity>
}

/** The outbox of composed, unacknowledged messages, in the order [org.hapticon.messaging.Outbox] defines. */
@Dao
interface OutboxDao {
    @Query("SELECT * FROM outbox WHERE next_attempt_at <= :now ORDER BY next_attempt_at, enqueued_at, rowid LIMIT :limit")
    suspend fun due(now: Long, limit: Int): List<OutboxEntity>

    @Query("SELECT * FROM outbox ORDER BY next_attempt_at, enqueued_at, rowid")
    suspend fun pending(): List<OutboxEntity>

    @Query("SELECT * FROM outbox ORDER BY next_attempt_at, enqueued_at, rowid")
    fun pendingStream(): Flow<List<OutboxEntity>>

    @Query("SELECT MIN(next_attempt_at) FROM outbox")
    suspend fun nextAttemptAt(): Long?

    @Insert(onConflict = OnConflictStrategy.IGNORE)
    suspend fun insertOrIgnore(entry: OutboxEntity): Long

    @Query("UPDATE outbox SET attempts = attempts + 1, last_error = :error, next_attempt_at = :next WHERE message_id = :id")
    suspend fun markFailed(id: String, error: String, next: Long)

    @Query("DELETE FROM outbox WHERE message_id = :id")
    suspend fun deleteEntry(id: String)

    /** The broker acknowledged [id]: due again at [next] unless its delivered receipt removes it first. */
    @Query("UPDATE outbox SET next_attempt_at = :next WHERE message_id = :id")
    suspend fun reschedule(id: String, next: Long)

    @Query("SELECT * FROM outbox WHERE message_id = :id")
    suspend fun entry(id: String): OutboxEntity?

    @Query("DELETE FROM outbox WHERE recipient = :peer")
    suspend fun deleteFor(peer: String)

    /** Makes an entry due at [now] (the user asked to retry it). */
    @Query("UPDATE outbox SET next_attempt_at = :now WHERE message_id = :id")
    suspend fun dueNow(id: String, now: Long)
}

/** The user's custom icons. */
@Dao
interface IconDao {
    @Query("SELECT * FROM icons ORDER BY name")
    fun icons(): Flow<List<IconEntity>>

    @Upsert
    suspend fun upsertIcon(icon: IconEntity)

    @Query("DELETE FROM icons WHERE name = :name")
    suspend fun deleteIcon(name: String)
}

/** The user's haptic patterns. */
@Dao
interface PatternDao {
    @Query("SELECT * FROM patterns ORDER BY name")
    fun patterns(): Flow<List<PatternEntity>>

    @Upsert
    suspend fun upsert(pattern: PatternEntity)

    @Query("DELETE FROM patterns WHERE name = :name")
    suspend fun delete(name: String)
}

/** Receipts waiting for a connection. */
@Dao
interface PendingReceiptDao {
    @Query("SELECT * FROM pending_receipts ORDER BY at, rowid")
    suspend fun pending(): List<PendingReceiptEntity>

    @Insert(onConflict = OnConflictStrategy.REPLACE)
    suspend fun upsert(receipt: PendingReceiptEntity)

    @Query("DELETE FROM pending_receipts WHERE message_id = :messageId AND state = :state")
    suspend fun delete(messageId: String, state: String)
}
