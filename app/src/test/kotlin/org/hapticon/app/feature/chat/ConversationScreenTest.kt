package org.hapticon.app.feature.chat

import android.content.Context
import android.os.Vibrator
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.test.core.app.ApplicationProvider
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.AdaptiveRenderer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.lastVibration
import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

@RunWith(RobolectricTestRunner::class)
class ConversationScreenTest {
    @get:Rule
    val compose = createComposeRule()

    private fun message(id: Int, outgoing: Boolean, state: MessageState, icon: HapticIcon? = null, sticker: String? = null) = StoredMessage(
        id = "0b7e7c1e-3f7b-4a57-9d3e-%012d".format(id), conversation = "bob", sender = if (outgoing) "alice" else "bob",
        sentAtMillis = 1L + id, text = "m$id", sticker = sticker, icon = icon, outgoing = outgoing, state = state, readAtMillis = null,
    )

    private fun state(messages: List<StoredMessage>, selected: HapticIcon? = null, feel: PeerFeel? = null) = ConversationUiState.Success(
        peer = "bob", messages = messages, icons = HapticIcon.PRESETS, selectedIcon = selected, selectedSticker = null, peerFeel = feel, error = null,
    )

    @Test
    fun iconChip_pressed_handsExactWaveformToVibrator() {
        val context = ApplicationProvider.getApplicationContext<Context>()
        val vibrator = context.getSystemService(Vibrator::class.java)
        shadowOf(vibrator).setHasAmplitudeControl(true)
        val player = AdaptiveHapticPlayer(vibrator, { DeviceCapabilities(true, true, 35) }, { null })
        compose.setContent {
            ConversationScreen(state(listOf(message(1, false, MessageState.RECEIVED, HapticIcon.KNOCK))), {}, {}, {}, {}, { player.play(it) }, {})
        }

        compose.onNodeWithContentDescription("Play haptic icon knock").performClick()

        assertEquals(RecordedVibration(listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), listOf(175, 111, 0, 175, 111, 0, 175, 111)), lastVibration(vibrator))
    }

    @Test
    @Config(qualifiers = "w400dp-h2000dp") // tall enough for every bubble above the composer
    fun ownMessages_everyState_visible() {
        val states = listOf(MessageState.SENDING, MessageState.SENT, MessageState.DELIVERED, MessageState.READ, MessageState.FAILED)
        compose.setContent {
            ConversationScreen(state(states.mapIndexed { i, s -> message(i, true, s) }), {}, {}, {}, {}, {}, {})
        }
        for (label in listOf("Sending…", "Sent", "Delivered", "Read", "Failed, retrying")) {
            compose.onNodeWithContentDescription("Message state: $label").assertExists()
        }
    }

    @Test
    fun composer_iconSelectedPeerKnown_showsHowItWillFeelThere() {
        compose.setContent {
            ConversationScreen(state(emptyList(), HapticIcon.HUG, PeerFeel(AdaptiveRenderer.ON_OFF, 61)), {}, {}, {}, {}, {}, {})
        }
        compose.onNodeWithText("How hug will feel there: on/off pattern, 61% fidelity").assertExists()
    }

    @Test
    fun sticker_received_shownAsImage() {
        compose.setContent {
            ConversationScreen(state(listOf(message(1, false, MessageState.RECEIVED, sticker = "heart"))), {}, {}, {}, {}, {}, {})
        }
        compose.onNodeWithContentDescription("Sticker: Heart").assertExists()
    }
}
