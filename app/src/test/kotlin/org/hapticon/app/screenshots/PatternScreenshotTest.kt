package org.hapticon.app.screenshots

import androidx.compose.ui.test.assertIsDisplayed
import androidx.compose.ui.test.hasScrollToKeyAction
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithTag
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollToKey
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.feature.chat.COMPOSER_ICONS_TAG
import org.hapticon.app.feature.chat.ChatClock
import org.hapticon.app.feature.chat.ConversationActions
import org.hapticon.app.feature.chat.ConversationScreen
import org.hapticon.app.feature.chat.ConversationUiState
import org.hapticon.app.feature.chat.PEER_FEEL_TAG
import org.hapticon.app.feature.chat.PeerFeel
import org.hapticon.app.feature.icons.IconsActions
import org.hapticon.app.feature.icons.IconsScreen
import org.hapticon.app.feature.icons.IconsUiState
import org.hapticon.app.feature.icons.PatternEditField
import org.hapticon.app.feature.icons.PatternEditorScreen
import org.hapticon.app.feature.icons.PatternEditorViewModel
import org.hapticon.app.feature.icons.PatternItem
import org.hapticon.app.feature.icons.PatternListActions
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.PatternPlan
import org.hapticon.app.study.TestHapticPlayer
import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.pattern.Transient
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import org.junit.Test
import java.time.ZoneOffset
import java.util.Locale

/** Haptic patterns in the app: the Icons tab's pattern section, the pattern editor, a pattern message. */
class PatternScreenshotTest : ScreenshotTest() {
    // A falling "boing" with a tap on top, and a slow swell sweeping up: the shapes AHAP and .haptic files hold.
    private val boing = HapticPattern(
        "boing",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.03, 1.0), AmplitudeKey(0.4, 0.0)),
        listOf(FrequencyKey(0.0, 300.0), FrequencyKey(0.4, 90.0)),
        listOf(Transient(0.0, 0.9, 0.8)),
    )
    private val swell = HapticPattern(
        "swell",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.8, 0.9), AmplitudeKey(1.2, 0.9), AmplitudeKey(1.6, 0.0)),
        listOf(FrequencyKey(0.0, 80.0), FrequencyKey(1.6, 240.0)),
    )

    // How an API 36 phone with a 120–280 Hz frequency profile plays them, as the app would compute it.
    private val phone = DeviceCapabilities(
        hasVibrator = true, hasAmplitudeControl = true, apiLevel = 36, envelopeEffectsSupported = true,
        frequencyRangeHz = 120.0..280.0, envelopeInfo = EnvelopeEffectInfo.GUARANTEED,
    )
    private val actions = PatternListActions({}, {}, {}, { _, _ -> }, {}, {})

    @Test
    fun icons_patternsImportedAndAnImportRefused() = screen(
        "icons-patterns",
        prepare = { compose.onNode(hasScrollToKeyAction()).performScrollToKey("patterns-header") },
    ) {
        IconsScreen(
            IconsUiState.Success(
                HapticIcon.PRESETS, RendererKind.ENVELOPE, nowPlaying = null,
                patterns = listOf(
                    PatternItem(boing, "boing.ahap", PatternPlan.of(phone, boing).summary),
                    PatternItem(swell, "swell.haptic", PatternPlan.of(phone, swell).summary),
                ),
                importMessage = "Not imported: huge.haptic: 2097152 bytes is larger than a pattern file may be (1048576 bytes)",
            ),
            IconsActions(),
            patternActions = actions,
        )
    }

    @Test
    fun patternEditor_octaveDownAndSofter_previewAndHowThisPhonePlaysIt() = screen("pattern-editor") {
        val fields = mapOf(
            PatternEditField.NAME to "swell low", PatternEditField.GAIN to "0.7",
            PatternEditField.SEMITONES to "-12", PatternEditField.TIME_SCALE to "1",
        )
        PatternEditorScreen(PatternEditorViewModel.validate(swell, fields, TestHapticPlayer()), { _, _ -> }, {}, {}, {})
    }

    @Test
    fun patternEditor_timeScaleOutOfRange_namesTheField() = screen("pattern-editor-error") {
        val fields = mapOf(
            PatternEditField.NAME to "swell", PatternEditField.GAIN to "1",
            PatternEditField.SEMITONES to "0", PatternEditField.TIME_SCALE to "19",
        )
        PatternEditorScreen(PatternEditorViewModel.validate(swell, fields, TestHapticPlayer()), { _, _ -> }, {}, {}, {})
    }

    @Test
    fun conversation_patternMessage_feelChipWithItsEnvelope_composerOffersPatternsAfterIcons() = screen(
        "chats-conversation-pattern",
        // The patterns follow the four presets in the composer's row: scroll it to them, as a user would.
        prepare = { compose.onNodeWithTag(COMPOSER_ICONS_TAG).performScrollToKey("pattern:swell") },
    ) { patternConversation() }

    /**
     * The same conversation at the largest font scale, scrolled at that scale: the row keeps its
     * scroll offset in pixels across a font change, so scrolling at 1.0 left a sliver of the "hug" chip under
     * the fading edge at 2.0. Scrolled to the chosen pattern, as a user would, it starts the row whole.
     */
    @Test
    fun conversation_patternMessage_largestFont_composerLinesWrapAndFieldStaysUsable() = screen(
        "chats-conversation-pattern",
        variants = listOf(Variant.LargestFont),
        prepare = {
            compose.onNodeWithTag(COMPOSER_ICONS_TAG).performScrollToKey("pattern:boing")
            // The "how it will feel there" lines, collapsed to one, leave the field and Send on the screen.
            compose.onNodeWithContentDescription("Message").assertIsDisplayed()
            compose.onNodeWithContentDescription("Send").assertIsDisplayed()
        },
    ) { patternConversation() }

    /**
     * The same at the largest font with the "how it will feel there" lines opened by a tap: every line whole (numbers
     * with their units), and still the field and Send on the screen; the message list gives way.
     */
    @Test
    fun conversation_patternChosen_largestFont_feelLinesExpanded() = screen(
        "chats-conversation-pattern-expanded",
        variants = listOf(Variant.LargestFont),
        prepare = {
            compose.onNodeWithTag(COMPOSER_ICONS_TAG).performScrollToKey("pattern:boing")
            compose.onNodeWithTag(PEER_FEEL_TAG).performClick()
            compose.onNodeWithContentDescription("Message").assertIsDisplayed()
            compose.onNodeWithContentDescription("Send").assertIsDisplayed()
        },
    ) { patternConversation() }

    @androidx.compose.runtime.Composable
    private fun patternConversation() {
        val now = 1_767_225_600_000L + 15 * 3_600_000L
        fun message(n: Int, outgoing: Boolean, state: MessageState, text: String, pattern: HapticPattern? = null) = StoredMessage(
            "0b7e7c1e-3f7b-4a57-9d3e-%012d".format(n), "bob", if (outgoing) "alice" else "bob", now - (10 - n) * 60_000L, text, null,
            null, outgoing, state, null, pattern = pattern,
        )
        ConversationScreen(
            ConversationUiState.Success(
                "bob",
                listOf(
                    message(1, false, MessageState.RECEIVED, "Made this in Haptics Studio", boing),
                    message(2, true, MessageState.FELT, "Ha, it bounces. Try mine", swell),
                    message(3, false, MessageState.RECEIVED, "Slow and rising, nice"),
                ),
                HapticIcon.PRESETS, null, null,
                // bob's Android 16 phone publishes a narrow frequency profile and its envelope limits: the lines under the
                // composer name the pitch and the control points it will play.
                PeerFeel.ofPattern(
                    Capabilities(
                        "bob", RendererKind.ENVELOPE, amplitudeControl = true, apiLevel = 36, resonantFrequencyHz = 170.0,
                        envelopeEffects = true, frequencyRangeHz = 120.0..240.0, pitchFit = PitchFit.OCTAVES,
                        envelopeLimits = EnvelopeEffectInfo.GUARANTEED,
                    ),
                    boing,
                ),
                null,
                patterns = listOf(boing, swell), selectedPattern = boing,
            ),
            ConversationActions(), ChatClock(ZoneOffset.UTC, Locale.UK), now,
        )
    }
}
