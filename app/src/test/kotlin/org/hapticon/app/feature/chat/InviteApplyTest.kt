package org.hapticon.app.feature.chat

import android.content.Context
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** Opening an invite link: what it adds and fills, and that a bad link changes nothing. */
@RunWith(RobolectricTestRunner::class)
class InviteApplyTest {
    private val db = Room.inMemoryDatabaseBuilder(ApplicationProvider.getApplicationContext<Context>(), HapticonDatabase::class.java)
        .allowMainThreadQueries().build()
    private val repository = OfflineFirstChatRepository(db)

    @After
    fun tearDown() = db.close()

    private fun peers() = runBlocking { repository.conversations().first().map { it.peer } }

    @Test
    fun newPhone_linkAddsTheContactAndFillsTheBroker() = runBlocking {
        val settings = InMemoryChatSettings()
        val outcome = applyInvite("hapticon://invite?user=bob&broker=tcp%3A%2F%2F192.168.1.20%3A1883", repository, settings)
        assertEquals(InviteOutcome.Added("bob", brokerFilled = true, note = null), outcome)
        assertEquals("tcp://192.168.1.20:1883", settings.preferences.value.brokerUrl)
        assertEquals(listOf("bob"), peers())
    }

    @Test
    fun brokerInUse_keptAndTheDifferenceSaid() = runBlocking {
        val settings = InMemoryChatSettings(ChatPreferences(userName = "alice", brokerUrl = "tcp://10.0.0.2:1883"))
        val outcome = applyInvite("hapticon://invite?user=bob&broker=192.168.1.20", repository, settings) as InviteOutcome.Added
        assertEquals("tcp://10.0.0.2:1883", settings.preferences.value.brokerUrl)
        assertEquals("bob uses tcp://192.168.1.20:1883; you stay on tcp://10.0.0.2:1883 (change it in Settings)", outcome.note)
        assertEquals(listOf("bob"), peers())
    }

    @Test
    fun hostileOrOwnLinks_rejectedWithOneLineAndNothingChanged() = runBlocking {
        val before = ChatPreferences(userName = "alice", brokerUrl = "")
        for ((link, reason) in listOf(
            "hapticon://invite?user=bob%2F%23&broker=h" to "Invite link's user name is not valid: use 1 to 32 letters, digits, '.', '_' or '-'",
            "hapticon://invite?user=bob&broker=tcp%3A%2F%2Fu%3Ap%40evil" to
                "Invite link's broker is not valid: broker URL \"tcp://u:p@evil\": put credentials in the settings, not the URL",
            "javascript:alert(1)" to "Not a Hapticon invite (expected hapticon://invite?…)",
            "hapticon://invite?user=alice&broker=h" to "This is your own invite",
        )) {
            val settings = InMemoryChatSettings(before)
            assertEquals(InviteOutcome.Rejected(reason), applyInvite(link, repository, settings))
            assertEquals(before, settings.preferences.value)
            assertEquals(emptyList<String>(), peers())
        }
    }
}
