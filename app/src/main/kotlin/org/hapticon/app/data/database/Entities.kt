package org.hapticon.app.data.database

import androidx.room.ColumnInfo
import androidx.room.Entity
import androidx.room.Index
import androidx.room.PrimaryKey
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PatternFiles
import org.hapticon.core.pattern.PatternFormat

/** A conversation with one peer, named by the peer's user name (one conversation per peer). */
@Entity(tableName = "conversations")
data class ConversationEntity(
    @PrimaryKey val peer: String,
    @ColumnInfo(name = "created_at") val createdAtMillis: Long,
)

/**
 * One chat message, own or received. The message id is the primary key, so a message delivered twice
 * (MQTT is at-least-once) is inserted once: inserts use IGNORE on conflict.
 *
 * The icon travels by value and is stored by value too (its JSON): a received custom icon stays playable
 * even though it is not in this user's icon library.
 */
@Entity(
    tableName = "messages",
    indices = [Index("conversation", "sent_at")],
)
data class MessageEntity(
    @PrimaryKey val id: String,
    val conversation: String,
    val sender: String,
    @ColumnInfo(name = "sent_at") val sentAtMillis: Long,
    val text: String,
    val sticker: String?,
    @ColumnInfo(name = "icon_json") val iconJson: String?,
    val outgoing: Boolean,
    /** A [MessageState] name. */
    val state: String,
    /** When the message was read: by the peer for own messages, by this user for received ones (added in v2). */
    @ColumnInfo(name = "read_at") val readAtMillis: Long? = null,
    /** The message's haptic pattern as pattern JSON ([patternToJson]), stored by value like the icon (added in v5). */
    @ColumnInfo(name = "pattern_json") val patternJson: String? = null,
)

/**
 * A composed message not yet acknowledged by the broker; its content is the [MessageEntity] with the
 * same id, written in the same transaction, so nothing composed is lost on process death.
 */
@Entity(tableName = "outbox")
data class OutboxEntity(
    @PrimaryKey @ColumnInfo(name = "message_id") val messageId: String,
    val recipient: String,
    /** Enqueue order, for equal due times (Outbox contract). */
    @ColumnInfo(name = "enqueued_at") val enqueuedAtMillis: Long,
    val attempts: Int = 0,
    @ColumnInfo(name = "next_attempt_at") val nextAttemptAtMillis: Long = 0,
    @ColumnInfo(name = "last_error") val lastError: String? = null,
)

/**
 * The id of every message received from [peer], kept apart from the message rows so that deleting a conversation
 * (its messages) does not forget them: a replayed genuine payload (recorded by the broker's operator, sealed and
 * signed by the peer) is then still a repeat, never a new message (added in v6). Kept for good (~100 bytes a row),
 * as `hapticon chat` keeps its `seen` ids: a window by sending time would refuse a message the peer's outbox still
 * resends after a long absence.
 */
@Entity(tableName = "seen_messages", primaryKeys = ["peer", "message_id"])
data class SeenMessageEntity(
    /** The sender, as the inbox topic proves it. */
    val peer: String,
    @ColumnInfo(name = "message_id") val messageId: String,
    /** When this device first stored it; for ids carried over from v5's message rows, the message's sending time. */
    @ColumnInfo(name = "seen_at") val seenAtMillis: Long,
)

/** A custom haptic icon the user made in the editor. */
@Entity(tableName = "icons")
data class IconEntity(
    @PrimaryKey val name: String,
    val attack: Double,
    val sustain: Double,
    val level: Double,
    val release: Double,
    val note: Double,
    val period: Double,
    val count: Int,
)

/** The icon; throws [org.hapticon.core.IconValidationException] for a row that is not a valid icon. */
fun IconEntity.asExternalModel(): HapticIcon = HapticIcon(name, attack, sustain, level, release, note, period, count)

fun HapticIcon.asEntity(): IconEntity = IconEntity(name, attack, sustain, level, release, note, period, count)

/**
 * A haptic pattern in the user's library: imported from an AHAP, `.haptic` or pattern JSON file, or saved from
 * the pattern editor (added in v5). Stored as pattern JSON, the format that keeps every field.
 *
 * @property source where it came from, shown in the list: the imported file's name, or null when made here.
 */
@Entity(tableName = "patterns")
data class PatternEntity(
    @PrimaryKey val name: String,
    val json: String,
    val source: String?,
    @ColumnInfo(name = "saved_at") val savedAtMillis: Long,
)

/** The pattern; throws [org.hapticon.core.pattern.PatternException] or a JSON error for a row that is not valid. */
fun PatternEntity.asExternalModel(): HapticPattern = patternFromJson(json)

/** [this] as a row. */
fun HapticPattern.asEntity(source: String?, savedAtMillis: Long): PatternEntity = PatternEntity(name, patternToJson(this), source, savedAtMillis)

/** [pattern] as pattern JSON, the stored form (it keeps every field). */
fun patternToJson(pattern: HapticPattern): String = PatternFiles.write(pattern, PatternFormat.JSON).text

/** The pattern in pattern JSON [json]; throws as [PatternFiles.read] does. */
fun patternFromJson(json: String): HapticPattern = PatternFiles.read(json.toByteArray(Charsets.UTF_8), PatternFormat.JSON, "pattern").pattern

/** How far a message got. Own messages go SENDING → SENT → DELIVERED → READ, or FAILED; received ones are RECEIVED. */
/**
 * An own message moves SENDING → SENT → DELIVERED → READ → FELT (FAILED after repeated send failures,
 * still retried); a received one is RECEIVED until read (READ). FELT is only ever an own message's state:
 * the peer played its icon.
 */
enum class MessageState { SENDING, SENT, DELIVERED, READ, FAILED, RECEIVED, FELT }

/** A message as the UI and sync see it. */
data class StoredMessage(
    val id: String,
    val conversation: String,
    val sender: String,
    val sentAtMillis: Long,
    val text: String,
    val sticker: String?,
    val icon: HapticIcon?,
    val outgoing: Boolean,
    val state: MessageState,
    val readAtMillis: Long?,
    /** The haptic pattern the message carries instead of an icon (message version 2), or null. */
    val pattern: HapticPattern? = null,
)

fun MessageEntity.asExternalModel(): StoredMessage = StoredMessage(
    id = id,
    conversation = conversation,
    sender = sender,
    sentAtMillis = sentAtMillis,
    text = text,
    sticker = sticker,
    // A row is written only from a valid icon; a bad one (corrupted storage) shows as a message without icon.
    icon = iconJson?.let { runCatching { IconJson.decode(it) }.getOrNull() },
    outgoing = outgoing,
    state = runCatching { MessageState.valueOf(state) }.getOrDefault(MessageState.FAILED),
    readAtMillis = readAtMillis,
    pattern = patternJson?.let { runCatching { patternFromJson(it) }.getOrNull() },
)

/**
 * A delivered or read receipt this device owes a peer but could not send (offline, broker down); sent
 * when the connection returns, then deleted (added in v3). One row per message and state.
 */
@Entity(tableName = "pending_receipts", primaryKeys = ["message_id", "state"])
data class PendingReceiptEntity(
    @ColumnInfo(name = "message_id") val messageId: String,
    /** A [org.hapticon.messaging.ReceiptState] wire name. */
    val state: String,
    /** Who the receipt goes to: the message's sender. */
    val peer: String,
    /** Who sends it: this device's user when it was owed. */
    @ColumnInfo(name = "from_user") val fromUser: String,
    @ColumnInfo(name = "at") val atMillis: Long,
)
