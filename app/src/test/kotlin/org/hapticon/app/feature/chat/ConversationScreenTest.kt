package org.hapticon.app.feature.chat

import org.hapticon.app.ui.Sticker
import android.content.Context
import android.os.Vibrator
import androidx.compose.runtime.collectAsState
import androidx.compose.runtime.getValue
import androidx.compose.ui.semantics.SemanticsActions
import androidx.compose.ui.test.assertIsDisplayed
import androidx.compose.ui.test.hasContentDescription
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithTag
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollToIndex
import androidx.compose.ui.test.performSemanticsAction
import androidx.compose.ui.unit.dp
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.flow.MutableStateFlow
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RecordedVibration
import org.hapticon.app.playback.lastVibration
import org.hapticon.app.playback.usageVibrator
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.platform.VibrationUsage
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
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
        val player = AdaptiveHapticPlayer(usageVibrator(vibrator), { DeviceCapabilities(true, true, 35) }, { null })
        compose.setContent {
            ConversationScreen(
                state(listOf(message(1, false, MessageState.RECEIVED, HapticIcon.KNOCK))),
                ConversationActions(onFeel = { player.play(it.icon!!, VibrationUsage.TOUCH) }),
            )
        }

        compose.onNode(feelChip("knock")).performClick()

        assertEquals(RecordedVibration(listOf(10L, 10L, 250L, 10L, 10L, 250L, 10L, 10L), listOf(175, 111, 0, 175, 111, 0, 175, 111)), lastVibration(vibrator))
    }

    @Test
    @Config(qualifiers = "w400dp-h2000dp") // tall enough for every bubble above the composer
    fun ownMessages_everyState_saidByTheBubble() {
        val states = listOf(MessageState.SENDING, MessageState.SENT, MessageState.DELIVERED, MessageState.READ, MessageState.FELT, MessageState.FAILED)
        val utc = ChatClock(java.time.ZoneOffset.UTC, java.util.Locale.UK)
        compose.setContent {
            ConversationScreen(state(states.mapIndexed { i, s -> message(i, true, s) }), ConversationActions(), utc)
        }
        for ((i, label) in listOf("Sending", "Sent", "Delivered", "Read", "Felt", "Not sent, tap to retry").withIndex()) {
            compose.onNodeWithContentDescription("You: m$i, 00:00, $label").assertExists()
        }
    }

    @Test
    fun receivedMessage_bubbleSaysWhoWhatWhichIconAndWhen_andItsTapFeelsIt() {
        val felt = mutableListOf<String>()
        val hug = message(1, false, MessageState.RECEIVED, HapticIcon.HUG, sticker = "heart")
        compose.setContent {
            ConversationScreen(state(listOf(hug)), ConversationActions(onFeel = { felt += it.id }), ChatClock(java.time.ZoneOffset.UTC, java.util.Locale.UK))
        }
        val bubble = compose.onNodeWithContentDescription("bob: Sticker: Heart, m1, Feel hug, 00:00")
        assertEquals("Feel hug", bubble.fetchSemanticsNode().config[SemanticsActions.OnClick].label)
        bubble.performSemanticsAction(SemanticsActions.OnClick)
        assertEquals(listOf(hug.id), felt)
    }

    @Test
    fun failedMessage_bubbleTapped_retriesThatMessage() {
        val failed = message(2, true, MessageState.FAILED)
        val retried = mutableListOf<String>()
        compose.setContent {
            ConversationScreen(state(listOf(message(1, true, MessageState.SENT), failed)), ConversationActions(onRetry = { retried += it.id }))
        }
        compose.onNodeWithText("m2").performClick()
        assertEquals(listOf(failed.id), retried)
    }

    /** The red words are themselves the target, at least 48 dp high, and TalkBack's double-tap on the bubble retries. */
    @Test
    fun failedMessage_redLineIsA48dpTarget_andTheBubblesTalkBackActionRetries() {
        val failed = message(2, true, MessageState.FAILED, HapticIcon.KNOCK)
        val retried = mutableListOf<String>()
        val felt = mutableListOf<String>()
        compose.setContent {
            ConversationScreen(
                state(listOf(message(1, true, MessageState.SENT), failed)),
                ConversationActions(onRetry = { retried += it.id }, onFeel = { felt += it.id }),
            )
        }
        // Drawn as a line under the bubble; Compose widens its touch target to 48 dp.
        val line = compose.onNodeWithText("Not sent, tap to retry")
        val touch = line.fetchSemanticsNode().touchBoundsInRoot
        val minimum = with(compose.density) { 48.dp.toPx() }
        assertTrue("touch target ${touch.width} × ${touch.height} px, under 48 dp ($minimum px)", touch.height >= minimum && touch.width >= minimum)
        line.performClick()
        assertEquals(listOf(failed.id), retried)

        val bubble = compose.onNode(hasContentDescription("You: m2, ", substring = true) and hasContentDescription(", Not sent, tap to retry", substring = true))
        val config = bubble.fetchSemanticsNode().config
        assertEquals("Retry sending", config[SemanticsActions.OnClick].label)
        bubble.performSemanticsAction(SemanticsActions.OnClick)
        assertEquals(listOf(failed.id, failed.id), retried)
        // Its icon can still be felt, from TalkBack's actions menu.
        val feel = config[SemanticsActions.CustomActions].single()
        assertEquals("Feel knock", feel.label)
        feel.action()
        assertEquals(listOf(failed.id), felt)
    }

    @Test
    fun longConversation_opensAtTheLatestMessage() {
        val messages = (1..60).map { message(it, it % 2 == 0, if (it % 2 == 0) MessageState.READ else MessageState.RECEIVED) }
        compose.setContent { ConversationScreen(state(messages), ConversationActions()) }
        compose.onNodeWithText("m60").assertIsDisplayed()
        compose.onNodeWithText("m1").assertDoesNotExist()
    }

    @Test
    fun newMessage_atTheBottom_followedButScrolledUp_jumpButtonCountsIt() {
        val messages = MutableStateFlow((1..60).map { message(it, false, MessageState.RECEIVED) })
        compose.setContent {
            val current by messages.collectAsState()
            ConversationScreen(state(current), ConversationActions())
        }
        messages.value = messages.value + message(61, false, MessageState.RECEIVED)
        compose.waitForIdle()
        compose.onNodeWithText("m61").assertIsDisplayed()

        // Scrolled up to the start, a new message is not followed: a button counts it instead.
        compose.onNodeWithTag(MESSAGE_LIST_TAG).performScrollToIndex(55)
        compose.waitForIdle()
        messages.value = messages.value + message(62, false, MessageState.RECEIVED)
        compose.waitForIdle()
        compose.onNodeWithText("m62").assertDoesNotExist()
        compose.onNodeWithText("1 new message", useUnmergedTree = true).performClick()
        compose.waitForIdle()
        compose.onNodeWithText("m62").assertIsDisplayed()
    }

    @Test
    @Config(qualifiers = "w400dp-h2000dp")
    fun dayChange_separatorsNameTheDays() {
        val day = 86_400_000L
        val now = 1_767_225_600_000L + 12 * 3_600_000L // 2026-01-01 12:00 UTC
        val messages = listOf(
            message(1, false, MessageState.RECEIVED).copy(sentAtMillis = now - 2 * day),
            message(2, true, MessageState.READ).copy(sentAtMillis = now - day),
            message(3, false, MessageState.RECEIVED).copy(sentAtMillis = now - 60_000),
        )
        compose.setContent {
            ConversationScreen(state(messages), ConversationActions(), ChatClock(java.time.ZoneOffset.UTC, java.util.Locale.UK), now)
        }
        compose.onNodeWithText("30 December 2025").assertExists()
        compose.onNodeWithText("Yesterday").assertExists()
        compose.onNodeWithText("Today").assertExists()
        compose.onNodeWithText("11:59").assertExists()
    }

    @Test
    fun composer_iconSelectedPeerKnown_showsHowItWillFeelThere() {
        compose.setContent {
            ConversationScreen(state(emptyList(), HapticIcon.HUG, PeerFeel(RendererKind.ON_OFF, 61)), ConversationActions())
        }
        compose.onNodeWithText("How hug will feel there: on/off pattern, 61% fidelity").assertExists()
    }

    @Test
    fun composer_envelopeLine_shownUnderThePitchLine() {
        val feel = PeerFeel(
            RendererKind.ENVELOPE, null, pitch = "bob's phone (120–240 Hz): 147 Hz → plays 147 Hz",
            envelope = "bob's envelope: 4 control points (7 merged into 4 by its limits: 4 points, 50 ms–1 s each, 4 s in all)",
        )
        compose.setContent { ConversationScreen(state(emptyList(), HapticIcon.HUG, feel), ConversationActions()) }
        compose.onNodeWithTag(PEER_FEEL_TAG).performClick() // collapsed to the first line by default (ComposerFeelLinesTest)
        compose.onNodeWithText("bob's phone (120–240\u00A0Hz): 147\u00A0Hz → plays 147\u00A0Hz").assertExists()
        compose.onNodeWithText("bob's envelope: 4 control points (7 merged into 4 by its limits: 4 points, 50\u00A0ms–1\u00A0s each, 4\u00A0s in all)").assertExists()
    }

    @Test
    fun composer_peerPublishedANarrowProfile_saysThePitchItsPhoneWillPlay() {
        val bob = Capabilities(
            "bob", RendererKind.ENVELOPE, amplitudeControl = true, apiLevel = 36, resonantFrequencyHz = 170.0,
            envelopeEffects = true, frequencyRangeHz = 120.0..240.0, pitchFit = PitchFit.OCTAVES,
        )
        val feel = MutableStateFlow(PeerFeel.ofIcon(bob, HapticIcon.STROKE))
        val selected = MutableStateFlow(HapticIcon.STROKE)
        compose.setContent {
            val f by feel.collectAsState()
            val icon by selected.collectAsState()
            ConversationScreen(state(emptyList(), icon, f), ConversationActions())
        }
        compose.onNodeWithTag(PEER_FEEL_TAG).performClick() // stays open while the peer's capabilities change
        compose.onNodeWithText("bob's phone (120–240\u00A0Hz): 349\u00A0Hz → plays 175\u00A0Hz, shifted down one octave").assertExists()
        // The peer switched to clamping: its next capabilities change the line.
        feel.value = PeerFeel.ofIcon(bob.copy(pitchFit = PitchFit.CLAMP), HapticIcon.STROKE)
        compose.onNodeWithText("bob's phone (120–240\u00A0Hz): 349\u00A0Hz → plays 240\u00A0Hz, clamped").assertExists()
        // A phone without a frequency profile: the note becomes sharpness.
        feel.value = PeerFeel.ofIcon(bob.copy(frequencyRangeHz = null), HapticIcon.STROKE)
        compose.onNodeWithText("bob's phone has no frequency profile: 349\u00A0Hz → sharpness 0.81").assertExists()
    }

    @Test
    fun sticker_received_shownAsImage() {
        compose.setContent {
            ConversationScreen(state(listOf(message(1, false, MessageState.RECEIVED, sticker = "heart"))), ConversationActions())
        }
        compose.onNodeWithContentDescription("Sticker: Heart").assertExists()
    }
}
