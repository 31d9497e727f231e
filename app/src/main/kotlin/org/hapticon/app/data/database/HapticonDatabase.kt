package org.hapticon.app.data.database

import android.content.Context
import androidx.room.AutoMigration
import androidx.room.Database
import androidx.room.Room
import androidx.room.RoomDatabase
import androidx.room.withTransaction
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
        PatternEntity::class, StudyProtocolEntity::class, StudySessionEntity::class, StudyEventEntity::class,
    ],
    // v2: messages.read_at (when a message was read); v3: pending_receipts; v4: the user-study tables;
    // v5: patterns and messages.pattern_json. All automatic migrations (new tables and nullable columns).
    version = 5,
    exportSchema = true,
    autoMigrations = [
        AutoMigration(from = 1, to = 2), AutoMigration(from = 2, to = 3), AutoMigration(from = 3, to = 4), AutoMigration(from = 4, to = 5),
    ],
)
abstract class HapticonDatabase : RoomDatabase(), StudyDatabase {
    abstract fun conversationDao(): ConversationDao
    abstract fun messageDao(): MessageDao
    abstract fun outboxDao(): OutboxDao
    abstract fun iconDao(): IconDao
    abstract fun pendingReceiptDao(): PendingReceiptDao
    abstract fun patternDao(): PatternDao
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
