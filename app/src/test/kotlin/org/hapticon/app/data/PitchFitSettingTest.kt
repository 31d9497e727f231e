package org.hapticon.app.data

import android.content.Context
import androidx.test.core.app.ApplicationProvider
import org.hapticon.core.pattern.PitchFit
import org.junit.Assert.assertEquals
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner

/** The pitch fit setting at rest: SharedPreferences `chat`, key `pitch_fit`, the [PitchFit] name. */
@RunWith(RobolectricTestRunner::class)
class PitchFitSettingTest {
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
}
