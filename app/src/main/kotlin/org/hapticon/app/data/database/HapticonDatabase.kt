package org.hapticon.app.data.database

import android.content.Context
import androidx.room.AutoMigration
import androidx.room.Database
import androidx.room.Room
import androidx.room.RoomDatabase

/**
 * The app's database: conversations, messages, the outbox of unsent messages and custom icons.
 * Schemas are exported to app/schemas and committed; every version change needs a migration there.
 */
@Database(
    entities = [ConversationEntity::class, MessageEntity::class, OutboxEntity::class, IconEntity::class, PendingReceiptEntity::class],
    // v2: messages.read_at (when a message was read); v3: pending_receipts. Both automatic migrations.
    version = 3,
    exportSchema = true,
    autoMigrations = [AutoMigration(from = 1, to = 2), AutoMigration(from = 2, to = 3)],
)
abstract class HapticonDatabase : RoomDatabase() {
    abstract fun conversationDao(): ConversationDao
    abstract fun messageDao(): MessageDao
    abstract fun outboxDao(): OutboxDao
    abstract fun iconDao(): IconDao
    abstract fun pendingReceiptDao(): PendingReceiptDao

    companion object {
        const val NAME = "hapticon.db"

        /** The on-disk database of the app. */
        fun create(context: Context): HapticonDatabase =
            Room.databaseBuilder(context.applicationContext, HapticonDatabase::class.java, NAME).build()
    }
}
