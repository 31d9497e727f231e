package org.hapticon.companion.chat

import kotlinx.coroutines.runBlocking
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.OutboxEntry
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.rules.TemporaryFolder
import java.io.File
import java.nio.file.Files
import java.nio.file.attribute.PosixFilePermissions

/** The CLI's outbox and seen ids in SQLite: what one process wrote, the next one reads. */
class ChatStoreTest {
    @get:Rule val temp = TemporaryFolder()

    private val file get() = File(temp.root, "alice/chat.db")

    @Test
    fun outbox_everyStateSurvivesReopening_inEnqueueOrder_onlyTheRecipientConfirms() = runBlocking {
        val first = ChatMessage.compose("alice", "first", icon = HapticIcon.KNOCK)
        val second = ChatMessage.compose("alice", "second")
        val third = ChatMessage.compose("alice", "", sticker = "hug")
        ChatStore.open(file).use { store ->
            store.enqueue("bob", first)
            store.enqueue("carol", second)
            store.enqueue("bob", third)
            store.enqueue("bob", first) // already pending: nothing changes
            store.markSent(first.id, resendAtMillis = 30_000)
            store.markFailed(second.id, "not connected", nextAttemptAtMillis = 2_000)
        }
        ChatStore.open(file).use { store ->
            assertEquals(
                listOf(
                    OutboxEntry("bob", first, attempts = 0, nextAttemptAtMillis = 30_000, awaitingReceipt = true),
                    OutboxEntry("carol", second, attempts = 1, nextAttemptAtMillis = 2_000, lastError = "not connected"),
                    OutboxEntry("bob", third),
                ),
                store.pending(),
            )
            assertEquals(listOf(second.id, third.id), store.due(nowMillis = 2_000, limit = 10).map { it.message.id })
            assertEquals(listOf(third.id), store.due(nowMillis = 1_999, limit = 10).map { it.message.id })
            assertEquals(0L, store.nextAttemptAt())
            assertFalse(store.markDelivered(first.id, by = "carol")) // a receipt from someone else confirms nothing
            assertTrue(store.markDelivered(first.id, by = "bob"))
            store.dueAll(nowMillis = 5)
            assertEquals(listOf(5L, 5L), store.pending().map { it.nextAttemptAtMillis })
        }
        ChatStore.open(file).use { store -> assertEquals(listOf(second.id, third.id), store.pending().map { it.message.id }) }
    }

    @Test
    fun seen_idsSurviveReopening_andTheFileIsTheUsersAlone() {
        val id = ChatMessage.compose("bob", "hi").id
        ChatStore.open(file).use { store ->
            assertTrue(store.firstSeen(id))
            assertFalse(store.firstSeen(id))
        }
        ChatStore.open(file).use { store ->
            assertFalse(store.firstSeen(id))
            assertEquals(1, store.seenCount)
        }
        assertEquals("rw-------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file.toPath())))
        assertEquals("rwx------", PosixFilePermissions.toString(Files.getPosixFilePermissions(file.parentFile.toPath())))
    }
}
