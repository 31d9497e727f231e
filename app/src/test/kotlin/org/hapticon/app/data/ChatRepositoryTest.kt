package org.hapticon.app.data

import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.test.runTest
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.OutboxEntity
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Receipt
import org.hapticon.messaging.ReceiptState
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

@RunWith(RobolectricTestRunner::class)
class ChatRepositoryTest {
    private lateinit var db: HapticonDatabase
    private lateinit var repository: OfflineFirstChatRepository
    private var now = 1_700_000_000_000L

    @Before
    fun setUp() {
        db = Room.inMemoryDatabaseBuilder(ApplicationProvider.getApplicationContext(), HapticonDatabase::class.java)
            .allowMainThreadQueries().build()
        repository = OfflineFirstChatRepository(db, clock = { now })
    }

    @After
    fun tearDown() = db.close()

    @Test
    fun send_textWithIcon_storesMessageAndOutboxEntryBeforeAnyNetwork() = runTest {
        val sent = repository.send("alice", "bob", "hello", icon = HapticIcon.HUG)

        val messages = repository.messages("bob").first()
        assertEquals(listOf(sent), messages)
        assertEquals("hello", sent.text)
        assertEquals(HapticIcon.HUG, sent.icon)
        assertEquals(MessageState.SENDING, sent.state)
        assertEquals(listOf(OutboxEntity(sent.id, "bob", enqueuedAtMillis = now)), db.outboxDao().pending())
        val entry = repository.pending().single()
        assertEquals(ChatMessage(sent.id, "alice", now, "hello", null, HapticIcon.HUG), entry.message)
    }

    @Test
    fun markSent_keepsTheEntryAwaitingTheReceipt_markDeliveredByTheRecipientRemovesIt() = runTest {
        val sent = repository.send("alice", "bob", "", sticker = "hug", icon = HapticIcon.HUG)

        repository.markSent(sent.id, resendAtMillis = now + 30_000)

        assertEquals(listOf(OutboxEntity(sent.id, "bob", now, nextAttemptAtMillis = now + 30_000)), db.outboxDao().pending())
        assertEquals(MessageState.SENT, repository.messages("bob").first().single().state)
        assertEquals(true, repository.pending().single().awaitingReceipt)
        // A failed resend does not make an acknowledged message look failed.
        repeat(3) { repository.markFailed(sent.id, "offline", now + 60_000) }
        assertEquals(MessageState.SENT, repository.messages("bob").first().single().state)

        assertFalse(repository.markDelivered(sent.id, by = "mallory"))
        assertTrue(repository.markDelivered(sent.id, by = "bob"))
        assertEquals(emptyList<OutboxEntity>(), db.outboxDao().pending())
        assertFalse(repository.markDelivered(sent.id, by = "bob"))
    }

    @Test
    fun markFailed_thirdFailure_showsFailedAndKeepsRetrying() = runTest {
        val sent = repository.send("alice", "bob", "hi")

        repository.markFailed(sent.id, "offline", now + 1_000)
        repository.markFailed(sent.id, "offline", now + 2_000)
        assertEquals(MessageState.SENDING, repository.messages("bob").first().single().state)
        repository.markFailed(sent.id, "offline", now + 4_000)

        assertEquals(MessageState.FAILED, repository.messages("bob").first().single().state)
        assertEquals(OutboxEntity(sent.id, "bob", now, attempts = 3, nextAttemptAtMillis = now + 4_000, lastError = "offline"), db.outboxDao().pending().single())
    }

    @Test
    fun receive_sameMessageTwice_storedOnce() = runTest {
        val message = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", now, "hi", icon = HapticIcon.KNOCK)

        assertTrue(repository.receive(message))
        assertFalse(repository.receive(message))

        val stored = repository.messages("bob").first()
        assertEquals(1, stored.size)
        assertEquals(MessageState.RECEIVED, stored.single().state)
        assertEquals(HapticIcon.KNOCK, stored.single().icon)
        assertEquals(listOf("bob"), repository.conversations().first().map { it.peer })
        assertEquals(1, repository.conversations().first().single().unread)
    }

    @Test
    fun applyReceipt_readThenLateDelivered_staysRead() = runTest {
        val sent = repository.send("alice", "bob", "hi")
        repository.markSent(sent.id, resendAtMillis = now + 30_000)

        repository.applyReceipt(Receipt(sent.id, "bob", ReceiptState.READ, now + 5))
        repository.applyReceipt(Receipt(sent.id, "bob", ReceiptState.DELIVERED, now + 1))

        val stored = repository.messages("bob").first().single()
        assertEquals(MessageState.READ, stored.state)
        assertEquals(now + 5, stored.readAtMillis)
    }

    @Test
    fun applyReceipt_fromAnotherUser_ignored() = runTest {
        val sent = repository.send("alice", "bob", "hi")

        repository.applyReceipt(Receipt(sent.id, "mallory", ReceiptState.READ, now))

        assertEquals(MessageState.SENDING, repository.messages("bob").first().single().state)
    }

    @Test
    fun markRead_unreadReceived_returnsThemOnce() = runTest {
        val message = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", now, "hi")
        repository.receive(message)

        assertEquals(listOf(message.id), repository.markRead("bob", now + 10).map { it.id })
        assertEquals(emptyList<String>(), repository.markRead("bob", now + 20).map { it.id })
        assertEquals(now + 10, repository.messages("bob").first().single().readAtMillis)
        assertNull(db.outboxDao().nextAttemptAt())
    }

    @Test
    fun iconRepository_savedCustomIcon_listedAfterPresets() = runTest {
        val icons = RoomIconRepository(db.iconDao())
        val custom = HapticIcon("buzz", 0.1, 0.2, 0.8, 0.1, 60.0, 0.0, 1)

        icons.save(custom)

        assertEquals(HapticIcon.PRESETS + custom, icons.icons().first())
    }
}
