package org.hapticon.app.feature.chat

import androidx.compose.runtime.collectAsState
import androidx.compose.runtime.getValue
import androidx.compose.ui.test.assertIsOff
import androidx.compose.ui.test.assertIsOn
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.render.RendererKind
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config

@RunWith(RobolectricTestRunner::class)
@Config(qualifiers = "w400dp-h2000dp")
class SettingsScreenTest {
    @get:Rule
    val compose = createComposeRule()

    @Test
    fun switches_changeTheStoredPreferences() {
        val settings = InMemoryChatSettings(ChatPreferences(userName = "alice", brokerUrl = "tcp://10.0.0.2:1883"))
        val reachable = mutableListOf<Boolean>()
        compose.setContent {
            val prefs by settings.preferences.collectAsState()
            SettingsScreen(
                SettingsUiState(prefs, listOf(RendererKind.AMPLITUDE_WAVEFORM, RendererKind.ON_OFF), "connected"),
                SettingsActions(update = settings::update, onStayReachable = { reachable += it }),
            )
        }
        compose.onNodeWithText("Tell senders when I felt their icon").assertIsOn().performClick()
        compose.onNodeWithText("Play icons when messages arrive").assertIsOff().performClick()
        compose.onNodeWithText("Colours from the wallpaper (Android 12+)").performClick()
        compose.onNodeWithText("Stay reachable when the app is closed").performClick()
        compose.onNodeWithText("Renderer").assertExists()
        compose.onNodeWithText("Automatic (best for this phone)").performClick()
        compose.onNodeWithText("on/off pattern").performClick()

        val prefs = settings.preferences.value
        assertEquals(false, prefs.sendFeltReceipts)
        assertEquals(true, prefs.autoPlay)
        assertEquals(true, prefs.dynamicColor)
        assertEquals("ON_OFF", prefs.rendererOverride)
        // "Stay reachable" goes through the route (it may ask for the notification permission first).
        assertEquals(listOf(true), reachable)
        compose.onNodeWithText("tcp://10.0.0.2:1883").assertExists()
        compose.onNodeWithText("Connection: connected").assertExists()
    }

    @Test
    fun pitchFit_octavesByDefault_clampChosenAndStored() {
        val settings = InMemoryChatSettings(ChatPreferences(userName = "alice", brokerUrl = "tcp://10.0.0.2:1883"))
        compose.setContent {
            val prefs by settings.preferences.collectAsState()
            SettingsScreen(SettingsUiState(prefs, listOf(RendererKind.ON_OFF), "connected"), SettingsActions(update = settings::update))
        }
        compose.onNodeWithText("Notes this phone cannot play").performScrollTo().assertExists()
        compose.onNodeWithText("Shift by octaves into range").performScrollTo().performClick()
        compose.onNodeWithText("Clamp to the nearest edge").performClick()
        assertEquals(PitchFit.CLAMP, settings.preferences.value.pitchFit)
        compose.onNodeWithText("Clamp to the nearest edge").assertExists()
    }

    @Test
    fun privacy_endToEndSwitchStored_warningsShown() {
        val settings = InMemoryChatSettings(ChatPreferences(userName = "alice", brokerUrl = "tcp://10.0.0.2:1883"))
        val warning = "bob's key changed (safety number now 12345, was 67890); message held back until you trust the new key"
        val trusted = mutableListOf<String>()
        compose.setContent {
            val prefs by settings.preferences.collectAsState()
            SettingsScreen(
                SettingsUiState(prefs, listOf(RendererKind.ON_OFF), "connected", securityWarnings = listOf(warning), changedKeys = setOf("bob")),
                SettingsActions(update = settings::update, onTrustKey = { trusted += it }),
            )
        }
        // On by default; off only through the dialog, and then the warning says so.
        compose.onNodeWithText("Encrypt messages end to end").performScrollTo().assertIsOn().performClick()
        compose.onNodeWithText("Keep encryption").performClick()
        assertEquals(true, settings.preferences.value.endToEnd)
        compose.onNodeWithText("Encrypt messages end to end").performScrollTo().assertIsOn().performClick()
        compose.onNodeWithText("Send messages unencrypted?").assertExists()
        compose.onNodeWithText("Turn encryption off").performClick()
        assertEquals(false, settings.preferences.value.endToEnd)
        compose.onNodeWithText(PLAINTEXT_WARNING).performScrollTo().assertExists()
        compose.onNodeWithText("Encrypt messages end to end").performScrollTo().assertIsOff().performClick() // on again: no question
        assertEquals(true, settings.preferences.value.endToEnd)
        compose.onNodeWithText(PLAINTEXT_WARNING).assertDoesNotExist()
        compose.onNodeWithText("⚠ $warning").performScrollTo().assertExists()
        compose.onNodeWithText("Trust bob's new key (safety numbers compared)").performScrollTo().performClick()
        assertEquals(listOf("bob"), trusted)
    }
}
