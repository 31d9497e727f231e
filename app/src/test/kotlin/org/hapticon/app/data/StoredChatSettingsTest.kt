package org.hapticon.app.data

import android.content.Context
import androidx.test.core.app.ApplicationProvider
import org.hapticon.core.pattern.PitchFit
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/**
 * Chat settings at rest in SharedPreferences `chat`: the pitch fit (key `pitch_fit`, the [PitchFit] name), and
 * end-to-end encryption, on by default and off only by a choice stored as such (`plaintext_chosen`).
 */
@RunWith(RobolectricTestRunner::class)
class StoredChatSettingsTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val prefs get() = context.getSharedPreferences("chat", Context.MODE_PRIVATE)

    // No Keystore on this JVM: the password (none here) would be kept in clear, which this test does not touch.
    private fun settings() = SharedPreferencesChatSettings(context, keystoreAvailable = { false })

    @Test
    fun default_octaves() {
        assertEquals(PitchFit.OCTAVES, settings().preferences.value.pitchFit)
    }

    @Test
    fun clamp_savedAndRereadByANewInstance() {
        settings().update { it.copy(pitchFit = PitchFit.CLAMP) }
        assertEquals("CLAMP", prefs.getString("pitch_fit", null))
        assertEquals(PitchFit.CLAMP, settings().preferences.value.pitchFit)
        settings().update { it.copy(pitchFit = PitchFit.OCTAVES) }
        assertEquals(PitchFit.OCTAVES, settings().preferences.value.pitchFit)
    }

    @Test
    fun unknownStoredName_fallsBackToOctaves() {
        prefs.edit().putString("pitch_fit", "STRETCH").commit()
        assertEquals(PitchFit.OCTAVES, settings().preferences.value.pitchFit)
    }

    @Test
    fun freshInstall_encrypts() {
        assertEquals(true, settings().preferences.value.endToEnd)
        assertEquals(true, ChatPreferences().endToEnd)
    }

    @Test
    fun earlierVersionsStoredDefault_doesNotCountAsAChoice() {
        // What every earlier version wrote with any other setting: its default, not the user's choice.
        prefs.edit().putBoolean("end_to_end", false).putString("user", "alice").commit()
        assertEquals(true, settings().preferences.value.endToEnd)
        settings().update { it.copy(autoPlay = true) }
        assertFalse(prefs.contains("end_to_end"))
        assertEquals(true, settings().preferences.value.endToEnd)
    }

    @Test
    fun plaintextChosen_storedAndReread_thenOnAgain() {
        settings().update { it.copy(endToEnd = false) }
        assertEquals(true, prefs.getBoolean("plaintext_chosen", false))
        assertEquals(false, settings().preferences.value.endToEnd)
        settings().update { it.copy(endToEnd = true) }
        assertEquals(true, settings().preferences.value.endToEnd)
    }
}
