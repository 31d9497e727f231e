package org.hapticon.app.data.database

import android.content.Context
import androidx.room.AutoMigration
import androidx.room.Database
import androidx.room.Room
import androidx.room.RoomDatabase
import androidx.room.migration.AutoMigrationSpec
import androidx.room.withTransaction
import androidx.sqlite.db.SupportSQLiteDatabase
import org.hapticon.app.study.StudyEventDao
import org.hapticon.app.study.StudyEventEntity
import org.hapticon.app.study.StudyProtocolDao
import org.hapticon.app.study.StudyDatabase
import org.hapticon.app.study.StudyProtocolEntity
import org.hapticon.app.study.StudySessionDao
import org.hapticon.app.study.StudySessionEntity

/**
 * The app's database: conversations, messages, the outbox of unsent messages, custom icons, and the
 * user-study protocols, sessions and their append-only event logs.
 * Schemas are exported to app/schemas and committed; every version change needs a migration there.
 */
@Database(
    entities = [
        ConversationEntity::class, MessageEntity::class, OutboxEntity::class, IconEntity::class, PendingReceiptEntity::class,
        PatternEntity::class, SeenMessageEntity::class, StudyProtocolEntity::class, StudySessionEntity::class, StudyEventEntity::class,
    ],
    // v2: messages.read_at (when a message was read); v3: pending_receipts; v4: the user-study tables;
    // v5: patterns and messages.pattern_json; v6: seen_messages, filled with the ids of v5's received messages
    // ([SeenIdsFromMessages]). All automatic migrations (new tables and nullable columns).
    version = 6,
    exportSchema = true,
    autoMigrations = [
        AutoMigration(from = 1, to = 2), AutoMigration(from = 2, to = 3), AutoMigration(from = 3, to = 4), AutoMigration(from = 4, to = 5),
        AutoMigration(from = 5, to = 6, spec = SeenIdsFromMessages::class),
    ],
)
abstract class HapticonDatabase : RoomDatabase(), StudyDatabase {
    abstract fun conversationDao(): ConversationDao
    abstract fun messageDao(): MessageDao
    abstract fun outboxDao(): OutboxDao
    abstract fun iconDao(): IconDao
    abstract fun pendingReceiptDao(): PendingReceiptDao
    abstract fun patternDao(): PatternDao
    abstract fun seenMessageDao(): SeenMessageDao
    abstract override fun studyProtocolDao(): StudyProtocolDao
    abstract override fun studySessionDao(): StudySessionDao
    abstract override fun studyEventDao(): StudyEventDao

    override suspend fun <R> inTransaction(block: suspend () -> R): R = withTransaction(block)

    companion object {
        const val NAME = "hapticon.db"

        /** The on-disk database of the app. */
        fun create(context: Context): HapticonDatabase =
            Room.databaseBuilder(context.applicationContext, HapticonDatabase::class.java, NAME).build()
    }
}

/**
 * v5 → v6: the new seen_messages table starts with the id of every received message already stored, so a message
 * received before the update is still refused as a replay after its conversation is deleted. v5 kept no arrival
 * time: the message's sending time stands in.
 */
class SeenIdsFromMessages : AutoMigrationSpec {
    override fun onPostMigrate(db: SupportSQLiteDatabase) {
        db.execSQL("INSERT OR IGNORE INTO seen_messages (peer, message_id, seen_at) SELECT sender, id, sent_at FROM messages WHERE outgoing = 0")
    }
}
