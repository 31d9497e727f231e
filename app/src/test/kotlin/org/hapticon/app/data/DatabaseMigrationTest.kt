package org.hapticon.app.data

import android.database.sqlite.SQLiteDatabase
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import java.io.File
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.runTest
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.data.database.IconEntity
import org.hapticon.app.data.database.MessageEntity
import org.hapticon.app.data.database.OutboxEntity
import org.hapticon.app.data.database.PatternEntity
import org.hapticon.app.data.database.SeenMessageEntity
import org.hapticon.app.data.database.asExternalModel
import org.hapticon.app.data.database.patternToJson
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.Transient
import org.hapticon.messaging.ChatMessage
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.PendingReceiptEntity
import org.hapticon.app.study.MaskingSetting
import org.hapticon.app.study.NoiseColor
import org.hapticon.app.study.RoomStudyRepository
import org.hapticon.app.study.StoredProtocol
import org.hapticon.study.OriginatingStudy
import org.json.JSONObject
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/**
 * Migrations, checked against the committed schema files. room-testing's MigrationTestHelper is not on
 * Maven Central (only Google's Maven), so this does what it does at the SQLite level: create the v1
 * database from the exported 1.json, fill it, and let Room open it at the current version.
 */
@RunWith(RobolectricTestRunner::class)
class DatabaseMigrationTest {
    private val context = ApplicationProvider.getApplicationContext<android.content.Context>()

    @Test
    fun migrate1To2_messageWritten_keptWithNullReadAt() = runTest {
        val file = context.getDatabasePath("migration-test.db").also { it.parentFile!!.mkdirs(); it.delete() }
        createFromSchema(file, version = 1)
        SQLiteDatabase.openDatabase(file.path, null, SQLiteDatabase.OPEN_READWRITE).use { v1 ->
            v1.execSQL("INSERT INTO conversations (peer, created_at) VALUES ('bob', 1)")
            v1.execSQL(
                "INSERT INTO messages (id, conversation, sender, sent_at, text, sticker, icon_json, outgoing, state) " +
                    "VALUES ('0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d', 'bob', 'bob', 5, 'kept', 'hug', NULL, 0, 'RECEIVED')",
            )
        }

        val db = Room.databaseBuilder(context, HapticonDatabase::class.java, file.path).allowMainThreadQueries().build()
        try {
            val message = db.messageDao().messages("bob").first().single()
            assertEquals("kept", message.text)
            assertEquals("hug", message.sticker)
            assertEquals(MessageState.RECEIVED.name, message.state)
            assertNull(message.readAtMillis)
            db.messageDao().updateStateAndReadAt(message.id, MessageState.READ.name, 42)
            assertEquals(42L, db.messageDao().message(message.id)!!.readAtMillis)
        } finally {
            db.close()
        }
    }

    @Test
    fun migrate2To3_messagesKeptAndReceiptsCanBeOwed() = runTest {
        val file = context.getDatabasePath("migration-2-3.db").also { it.parentFile!!.mkdirs(); it.delete() }
        createFromSchema(file, version = 2)
        SQLiteDatabase.openDatabase(file.path, null, SQLiteDatabase.OPEN_READWRITE).use { v2 ->
            v2.execSQL("INSERT INTO conversations (peer, created_at) VALUES ('bob', 1)")
            v2.execSQL(
                "INSERT INTO messages (id, conversation, sender, sent_at, text, sticker, icon_json, outgoing, state, read_at) " +
                    "VALUES ('0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d', 'bob', 'bob', 5, 'kept', NULL, NULL, 0, 'READ', 9)",
            )
        }

        val db = Room.databaseBuilder(context, HapticonDatabase::class.java, file.path).allowMainThreadQueries().build()
        try {
            val message = db.messageDao().messages("bob").first().single()
            assertEquals("kept", message.text)
            assertEquals(9L, message.readAtMillis)
            assertEquals(emptyList<PendingReceiptEntity>(), db.pendingReceiptDao().pending())
            val owed = PendingReceiptEntity(message.id, "read", "bob", "alice", 9)
            db.pendingReceiptDao().upsert(owed)
            db.pendingReceiptDao().upsert(owed.copy(atMillis = 10)) // the same receipt again replaces it
            assertEquals(listOf(owed.copy(atMillis = 10)), db.pendingReceiptDao().pending())
        } finally {
            db.close()
        }
    }

    @Test
    fun migrate3To4_chatRowsKeptAndStudyTablesWork() = runTest {
        val file = context.getDatabasePath("migration-3-4.db").also { it.parentFile!!.mkdirs(); it.delete() }
        createFromSchema(file, version = 3)
        SQLiteDatabase.openDatabase(file.path, null, SQLiteDatabase.OPEN_READWRITE).use { v3 ->
            v3.execSQL("INSERT INTO conversations (peer, created_at) VALUES ('bob', 1)")
            v3.execSQL(
                "INSERT INTO messages (id, conversation, sender, sent_at, text, sticker, icon_json, outgoing, state, read_at) " +
                    "VALUES ('0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d', 'bob', 'bob', 5, 'kept', 'hug', NULL, 0, 'READ', 9)",
            )
            v3.execSQL("INSERT INTO pending_receipts (message_id, state, peer, from_user, at) VALUES ('0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d', 'read', 'bob', 'alice', 9)")
        }

        val db = Room.databaseBuilder(context, HapticonDatabase::class.java, file.path).allowMainThreadQueries().build()
        try {
            val message = db.messageDao().messages("bob").first().single()
            assertEquals("kept", message.text)
            assertEquals(9L, message.readAtMillis)
            assertEquals(listOf("read"), db.pendingReceiptDao().pending().map { it.state })

            val study = RoomStudyRepository(db)
            val own = StoredProtocol(OriginatingStudy.PROTOCOL.copy(id = "mine"), seed = 7, masking = MaskingSetting(NoiseColor.WHITE, -40.0))
            study.saveProtocol(own)
            assertEquals(StoredProtocol.BUILT_IN + own, study.protocols().first())
            val session = study.startSession(own, 1_700_000_000_000L)
            assertEquals("P000-A", session.participant)
            assertEquals(listOf("session_started"), study.entries(session.id).map { it.type })
            assertEquals("P001-D", study.startSession(own, 1_700_000_001_000L).participant)
        } finally {
            db.close()
        }
    }

    @Test
    fun migrate4To5_rowsKeptExactlyAndPatternsStored() = runTest {
        val file = context.getDatabasePath("migration-4-5.db").also { it.parentFile!!.mkdirs(); it.delete() }
        createFromSchema(file, version = 4)
        SQLiteDatabase.openDatabase(file.path, null, SQLiteDatabase.OPEN_READWRITE).use { v4 ->
            v4.execSQL("INSERT INTO conversations (peer, created_at) VALUES ('bob', 1)")
            v4.execSQL(
                "INSERT INTO messages (id, conversation, sender, sent_at, text, sticker, icon_json, outgoing, state, read_at) " +
                    "VALUES ('0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d', 'bob', 'bob', 5, 'kept', 'hug', NULL, 0, 'READ', 9)",
            )
            v4.execSQL("INSERT INTO icons (name, attack, sustain, level, release, note, period, count) VALUES ('mine', 0.1, 0.2, 0.5, 0.3, 60, 0, 1)")
        }

        val db = Room.databaseBuilder(context, HapticonDatabase::class.java, file.path).allowMainThreadQueries().build()
        try {
            assertEquals(
                MessageEntity("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", "bob", 5, "kept", "hug", null, false, "READ", 9, patternJson = null),
                db.messageDao().message("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d"),
            )
            assertEquals(listOf(IconEntity("mine", 0.1, 0.2, 0.5, 0.3, 60.0, 0.0, 1)), db.iconDao().icons().first())
            assertEquals(emptyList<PatternEntity>(), db.patternDao().patterns().first())

            val boing = HapticPattern("boing", listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.05, 1.0), AmplitudeKey(0.4, 0.0)),
                listOf(FrequencyKey(0.0, 220.0), FrequencyKey(0.4, 110.0)), listOf(Transient(0.1, 0.8, 0.4)))
            RoomPatternRepository(db.patternDao(), clock = { 77 }).save(boing, source = "boing.ahap")
            val row = db.patternDao().patterns().first().single()
            assertEquals(PatternEntity("boing", patternToJson(boing), "boing.ahap", 77), row)
            assertEquals(boing, row.asExternalModel())

            // A received pattern message keeps its pattern by value, like an icon.
            val repository = OfflineFirstChatRepository(db)
            val message = ChatMessage("1b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", 6, "", pattern = boing)
            repository.receive(message)
            assertEquals(patternToJson(boing), db.messageDao().message(message.id)!!.patternJson)
            assertEquals(boing, repository.message(message.id)!!.pattern)
        } finally {
            db.close()
        }
    }

    /**
     * v6 keeps received ids apart from the messages: v5's received messages become seen ids (its own messages do not),
     * every row stays as it was, and once the conversation is deleted those ids still refuse a replay.
     */
    @Test
    fun migrate5To6_receivedIdsSeen_rowsKept_replayAfterDeleteRefused() = runTest {
        val file = context.getDatabasePath("migration-5-6.db").also { it.parentFile!!.mkdirs(); it.delete() }
        createFromSchema(file, version = 5)
        val received = "0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d"
        val own = "2b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d"
        SQLiteDatabase.openDatabase(file.path, null, SQLiteDatabase.OPEN_READWRITE).use { v5 ->
            v5.execSQL("INSERT INTO conversations (peer, created_at) VALUES ('bob', 1)")
            v5.execSQL(
                "INSERT INTO messages (id, conversation, sender, sent_at, text, sticker, icon_json, outgoing, state, read_at, pattern_json) " +
                    "VALUES ('$received', 'bob', 'bob', 5, 'meet at 5', 'hug', NULL, 0, 'READ', 9, NULL)",
            )
            v5.execSQL(
                "INSERT INTO messages (id, conversation, sender, sent_at, text, sticker, icon_json, outgoing, state, read_at, pattern_json) " +
                    "VALUES ('$own', 'bob', 'alice', 7, 'ok', NULL, NULL, 1, 'DELIVERED', NULL, NULL)",
            )
            v5.execSQL("INSERT INTO outbox (message_id, recipient, enqueued_at, attempts, next_attempt_at, last_error) VALUES ('$own', 'bob', 7, 1, 30007, NULL)")
        }

        val db = Room.databaseBuilder(context, HapticonDatabase::class.java, file.path).allowMainThreadQueries().build()
        try {
            assertEquals(
                listOf(
                    MessageEntity(received, "bob", "bob", 5, "meet at 5", "hug", null, false, "READ", 9),
                    MessageEntity(own, "bob", "alice", 7, "ok", null, null, true, "DELIVERED", null),
                ),
                db.messageDao().all(),
            )
            assertEquals(listOf(OutboxEntity(own, "bob", 7, 1, 30007, null)), db.outboxDao().pending())
            // The received id is seen, with its sending time standing in for the arrival v5 did not keep.
            assertEquals(listOf(SeenMessageEntity("bob", received, 5)), db.seenMessageDao().seenFrom("bob"))
            assertEquals(emptyList<SeenMessageEntity>(), db.seenMessageDao().seenFrom("alice"))

            val repository = OfflineFirstChatRepository(db, clock = { 100 })
            repository.deleteConversation("bob")
            assertEquals(emptyList<MessageEntity>(), db.messageDao().all())
            val replay = ChatMessage(received, "bob", 5, "meet at 5", "hug")
            assertEquals(false, repository.receive(replay))
            assertEquals(emptyList<MessageEntity>(), db.messageDao().all())
            assertEquals(emptyList<String>(), db.conversationDao().conversationSummaries().first().map { it.peer })
            assertEquals(listOf(SeenMessageEntity("bob", received, 5)), db.seenMessageDao().seenFrom("bob"))
        } finally {
            db.close()
        }
    }

    @Test
    fun schema6_exported_addsTheSeenMessagesTable() {
        val tables = schema(6).getJSONObject("database").getJSONArray("entities")
        val byName = (0 until tables.length()).associate { tables.getJSONObject(it).getString("tableName") to tables.getJSONObject(it) }
        assertEquals(
            "CREATE TABLE IF NOT EXISTS `\${TABLE_NAME}` (`peer` TEXT NOT NULL, `message_id` TEXT NOT NULL, `seen_at` INTEGER NOT NULL, " +
                "PRIMARY KEY(`peer`, `message_id`))",
            byName.getValue("seen_messages").getString("createSql"),
        )
    }

    @Test
    fun schema5_exported_addsThePatternsTableAndColumn() {
        val tables = schema(5).getJSONObject("database").getJSONArray("entities")
        val byName = (0 until tables.length()).associate { tables.getJSONObject(it).getString("tableName") to tables.getJSONObject(it) }
        assertEquals(
            "CREATE TABLE IF NOT EXISTS `\${TABLE_NAME}` (`name` TEXT NOT NULL, `json` TEXT NOT NULL, `source` TEXT, " +
                "`saved_at` INTEGER NOT NULL, PRIMARY KEY(`name`))",
            byName.getValue("patterns").getString("createSql"),
        )
        assertTrue(byName.getValue("messages").getString("createSql").contains("`pattern_json` TEXT"))
    }

    @Test
    fun schema4_exported_addsTheStudyTables() {
        val tables = schema(4).getJSONObject("database").getJSONArray("entities")
        val names = (0 until tables.length()).map { tables.getJSONObject(it).getString("tableName") }.sorted()
        assertEquals(
            listOf("conversations", "icons", "messages", "outbox", "pending_receipts", "study_events", "study_protocols", "study_sessions"),
            names,
        )
    }

    @Test
    fun schema3_exported_matchesEntities() {
        val tables = schema(3).getJSONObject("database").getJSONArray("entities")
        val names = (0 until tables.length()).map { tables.getJSONObject(it).getString("tableName") }.sorted()
        assertEquals(listOf("conversations", "icons", "messages", "outbox", "pending_receipts"), names)
    }

    @Test
    fun schema2_exported_matchesEntities() {
        val tables = schema(2).getJSONObject("database").getJSONArray("entities")
        val names = (0 until tables.length()).map { tables.getJSONObject(it).getString("tableName") }.sorted()
        assertEquals(listOf("conversations", "icons", "messages", "outbox"), names)
    }

    private fun createFromSchema(file: File, version: Int) {
        val database = schema(version).getJSONObject("database")
        SQLiteDatabase.openOrCreateDatabase(file, null).use { db ->
            val entities = database.getJSONArray("entities")
            for (i in 0 until entities.length()) {
                val entity = entities.getJSONObject(i)
                val table = entity.getString("tableName")
                db.execSQL(entity.getString("createSql").replace("\${TABLE_NAME}", table))
                val indices = entity.optJSONArray("indices")
                for (j in 0 until (indices?.length() ?: 0)) {
                    db.execSQL(indices!!.getJSONObject(j).getString("createSql").replace("\${TABLE_NAME}", table))
                }
            }
            val setup = database.getJSONArray("setupQueries")
            for (i in 0 until setup.length()) db.execSQL(setup.getString(i))
            db.version = version
        }
    }

    private fun schema(version: Int): JSONObject {
        // Tests run with the module directory or the repository root as working directory.
        val relative = "schemas/org.hapticon.app.data.database.HapticonDatabase/$version.json"
        val file = listOf(File(relative), File("app/$relative")).first { it.exists() }
        return JSONObject(file.readText())
    }
}
