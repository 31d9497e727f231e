package org.hapticon.app.data

import android.content.Context
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.test.runTest
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.junit.Assert.assertEquals
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

@RunWith(RobolectricTestRunner::class)
class ProcessDeathTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()

    @Test
    fun outbox_databaseReopened_composedMessageStillPending() = runTest {
        context.deleteDatabase("death.db")
        val now = 1_700_000_000_000L
        val first = Room.databaseBuilder(context, HapticonDatabase::class.java, "death.db").build()
        val sent = OfflineFirstChatRepository(first, clock = { now }).send("alice", "bob", "before the crash", icon = HapticIcon.STROKE)
        first.close() // the process dies before any network call

        val second = Room.databaseBuilder(context, HapticonDatabase::class.java, "death.db").build()
        try {
            val pending = OfflineFirstChatRepository(second, clock = { now }).pending()
            assertEquals(listOf(ChatMessage(sent.id, "alice", now, "before the crash", null, HapticIcon.STROKE)), pending.map { it.message })
            assertEquals(listOf("bob"), pending.map { it.recipient })
        } finally {
            second.close()
        }
    }
}
