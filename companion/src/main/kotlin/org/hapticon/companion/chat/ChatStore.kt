package org.hapticon.companion.chat

import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Decoded
import org.hapticon.messaging.Deduplicator
import org.hapticon.messaging.MessageCodec
import org.hapticon.messaging.Outbox
import org.hapticon.messaging.OutboxEntry
import org.hapticon.messaging.Topics
import java.io.File
import java.nio.file.Files
import java.nio.file.attribute.PosixFilePermissions
import java.sql.Connection
import java.sql.DriverManager
import java.sql.ResultSet
import java.sql.SQLException

/**
 * What `hapticon chat` must not forget when it exits, in one SQLite file (`chat.db`, mode 600): the [Outbox] of
 * messages the receiver has not confirmed yet, and, as [Deduplicator], the id of every message shown, so that a
 * repeat or a replayed payload is never shown as new, not even in a later session.
 *
 * SQLite rather than a hand-written append-only file: the outbox is updated in place (sent, failed, confirmed), which
 * a log would need compaction and torn-record recovery for; SQLite's journal gives atomic, durable transactions, and
 * sqlite-jdbc is already the collector's store. Write-ahead log with `synchronous=FULL`, so every change is fsynced
 * before the call returns (sqlite.org/pragma.html#pragma_synchronous): a message typed and acknowledged on screen
 * survives a crash or power cut. Two chats of one user may share the file (SQLite locks it; a busy writer is waited
 * for up to [BUSY_TIMEOUT_MILLIS]); both then resend, and receivers drop the repeats by id.
 *
 * Seen ids are kept for good (a UUID per row, ~100 bytes): a window by sending time would have to refuse messages
 * older than the window, and an outbox resends an unconfirmed message for as long as its receiver stays away.
 * One connection, used under this object's lock; thread-safe.
 */
class ChatStore private constructor(
    /** The database file. */
    val file: File,
    private val db: Connection,
) : Outbox, Deduplicator, AutoCloseable {

    override suspend fun enqueue(recipient: String, message: ChatMessage) {
        Topics.requireUserName(recipient)
        update(
            "INSERT OR IGNORE INTO outbox(message_id, recipient, payload, attempts, next_attempt_at, last_error, awaiting_receipt) VALUES (?, ?, ?, 0, 0, NULL, 0)",
            message.id, recipient, MessageCodec.encode(message),
        )
    }

    override suspend fun due(nowMillis: Long, limit: Int): List<OutboxEntry> {
        require(limit >= 0) { "limit must be >= 0, was $limit" }
        return entries("WHERE next_attempt_at <= ? ORDER BY seq LIMIT ?", nowMillis, limit)
    }

    override suspend fun nextAttemptAt(): Long? = synchronized(this) {
        db.prepareStatement("SELECT MIN(next_attempt_at) FROM outbox").use { s -> s.executeQuery().use { r -> r.next(); r.getLong(1).takeUnless { r.wasNull() } } }
    }

    override suspend fun markSent(messageId: String, resendAtMillis: Long) {
        update("UPDATE outbox SET awaiting_receipt = 1, next_attempt_at = ? WHERE message_id = ?", resendAtMillis, messageId)
    }

    override suspend fun markDelivered(messageId: String, by: String): Boolean =
        update("DELETE FROM outbox WHERE message_id = ? AND recipient = ?", messageId, by) > 0

    override suspend fun markFailed(messageId: String, error: String, nextAttemptAtMillis: Long) {
        update("UPDATE outbox SET attempts = attempts + 1, next_attempt_at = ?, last_error = ? WHERE message_id = ?", nextAttemptAtMillis, error, messageId)
    }

    override suspend fun pending(): List<OutboxEntry> = entries("ORDER BY seq")

    /**
     * Makes every entry due at [nowMillis], confirmed or not by the broker: a new session sends everything unconfirmed
     * once at once (the previous one may have ended long ago, and a broker may have lost what it acknowledged).
     */
    fun dueAll(nowMillis: Long) {
        update("UPDATE outbox SET next_attempt_at = ?", nowMillis)
    }

    /** Records [messageId] as shown; true the first time, in this session or any earlier one. */
    override fun firstSeen(messageId: String): Boolean =
        update("INSERT OR IGNORE INTO seen(message_id, seen_at) VALUES (?, ?)", messageId, System.currentTimeMillis()) > 0

    /** How many message ids are remembered as seen. */
    val seenCount: Int
        get() = synchronized(this) { db.prepareStatement("SELECT COUNT(*) FROM seen").use { s -> s.executeQuery().use { r -> r.next(); r.getInt(1) } } }

    override fun close() = synchronized(this) { db.close() }

    private fun update(sql: String, vararg values: Any?): Int = synchronized(this) {
        db.prepareStatement(sql).use { s ->
            bind(s, values)
            s.executeUpdate()
        }
    }

    private fun entries(where: String, vararg values: Any?): List<OutboxEntry> = synchronized(this) {
        db.prepareStatement("SELECT message_id, recipient, payload, attempts, next_attempt_at, last_error, awaiting_receipt FROM outbox $where").use { s ->
            bind(s, values)
            s.executeQuery().use { r -> generateSequence { if (r.next()) entry(r) else null }.toList() }
        }
    }

    private fun entry(r: ResultSet): OutboxEntry {
        val id = r.getString(1)
        // Written by MessageCodec.encode above; a row that no longer decodes was altered outside this program.
        val message = when (val decoded = MessageCodec.decodeInbox(r.getBytes(3))) {
            is Decoded.Accepted -> decoded.value as? ChatMessage
            is Decoded.Rejected -> null
        }
        if (message == null || message.id != id) throw SQLException("outbox row $id in $file does not hold its message; delete the row or the file")
        return OutboxEntry(r.getString(2), message, r.getInt(4), r.getLong(5), r.getString(6), r.getInt(7) != 0)
    }

    private fun bind(s: java.sql.PreparedStatement, values: Array<out Any?>) {
        values.forEachIndexed { i, v -> s.setObject(i + 1, v) }
    }

    companion object {
        /** How long a write waits for another process holding the file. */
        const val BUSY_TIMEOUT_MILLIS: Int = 5_000

        /**
         * Opens (creating it, mode 600, in a directory made mode 700) the store at [file]. Throws [SQLException] when
         * the file is not a SQLite database or cannot be written.
         */
        fun open(file: File): ChatStore {
            val dir = file.absoluteFile.parentFile
            if (!dir.isDirectory) {
                runCatching { Files.createDirectories(dir.toPath(), PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------"))) }
                    .onFailure { dir.mkdirs() } // not POSIX (Windows): the user's profile folder protects it
            }
            if (!file.exists()) {
                runCatching { Files.createFile(file.toPath(), PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------"))) }
            }
            val db = DriverManager.getConnection("jdbc:sqlite:${file.path}")
            try {
                db.createStatement().use { s ->
                    s.execute("PRAGMA busy_timeout = $BUSY_TIMEOUT_MILLIS")
                    s.execute("PRAGMA journal_mode = WAL")
                    s.execute("PRAGMA synchronous = FULL")
                    s.execute(
                        "CREATE TABLE IF NOT EXISTS outbox (seq INTEGER PRIMARY KEY AUTOINCREMENT, message_id TEXT NOT NULL UNIQUE, recipient TEXT NOT NULL, " +
                            "payload BLOB NOT NULL, attempts INTEGER NOT NULL, next_attempt_at INTEGER NOT NULL, last_error TEXT, awaiting_receipt INTEGER NOT NULL)",
                    )
                    s.execute("CREATE TABLE IF NOT EXISTS seen (message_id TEXT PRIMARY KEY, seen_at INTEGER NOT NULL) WITHOUT ROWID")
                }
            } catch (e: SQLException) {
                db.close()
                throw e
            }
            return ChatStore(file, db)
        }
    }
}
