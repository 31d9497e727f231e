package org.hapticon.app.screenshots

import android.view.View
import androidx.compose.foundation.background
import androidx.compose.foundation.layout.Arrangement
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.Row
import androidx.compose.foundation.layout.WindowInsets
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.height
import androidx.compose.foundation.layout.ime
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.layout.windowInsetsBottomHeight
import androidx.compose.foundation.shape.RoundedCornerShape
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.graphics.Color
import androidx.compose.ui.platform.LocalDensity
import androidx.compose.ui.platform.LocalView
import androidx.compose.ui.semantics.clearAndSetSemantics
import androidx.compose.ui.test.hasSetTextAction
import androidx.compose.ui.test.performTextInput
import androidx.compose.ui.text.style.TextAlign
import androidx.compose.ui.unit.dp
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.feature.chat.ChatClock
import org.hapticon.app.feature.chat.ConversationActions
import org.hapticon.app.feature.chat.ConversationScreen
import org.hapticon.app.feature.chat.ConversationUiState
import org.hapticon.app.feature.chat.PeerFeel
import org.hapticon.app.feature.chat.openKeyboard
import org.hapticon.core.HapticIcon
import org.hapticon.core.render.RendererKind
import org.junit.Test
import org.robolectric.annotation.Config
import java.time.ZoneOffset
import java.util.Locale

/**
 * A conversation on a small phone (360 × 780 dp, a common Android size) with the keyboard up, at the default and
 * the largest font scale: the composer sits on the keyboard and the latest message stays above it.
 *
 * Robolectric draws no keyboard window, so the keyboard is dispatched as what the app sees of it, its insets (300 dp,
 * a typical Gboard with its suggestion strip), and a plain stand-in is drawn in the space they take: a grey panel of
 * key caps, only so that the picture shows where the real keyboard would be.
 */
@Config(qualifiers = "w360dp-h780dp-xxhdpi")
class SmallPhoneScreenshotTest : ScreenshotTest() {
    private val now = 1_767_225_600_000L + 15 * 3_600_000L + 42 * 60_000L // 2026-01-01 15:42 UTC
    private val clock = ChatClock(ZoneOffset.UTC, Locale.UK)
    private lateinit var view: View

    private fun message(n: Int, outgoing: Boolean, state: MessageState, minutesAgo: Int, text: String, icon: HapticIcon? = null) =
        StoredMessage("0b7e7c1e-3f7b-4a57-9d3e-%012d".format(n), "bob", if (outgoing) "alice" else "bob", now - minutesAgo * 60_000L, text, null, icon, outgoing, state, null)

    private val messages = listOf(
        message(1, false, MessageState.RECEIVED, 30, "Are you coming to the lab?"),
        message(2, true, MessageState.READ, 20, "Yes, in ten minutes"),
        message(3, false, MessageState.RECEIVED, 2, "Great, feel this when you are here", HapticIcon.KNOCK),
    )

    /** The keyboard's insets, as Android dispatches them to the window when it opens, and a reply being typed. */
    private fun typeWithTheKeyboardUp() {
        compose.runOnIdle { openKeyboard(view, KEYBOARD_DP) }
        compose.onNode(hasSetTextAction()).performTextInput("On my way")
    }

    @Test
    fun conversation_keyboardUp_composerOnTheKeyboardLatestMessageAbove() = screen(
        "chats-conversation-keyboard-360dp",
        variants = listOf(Variant.Light, Variant.LargestFont),
        prepare = ::typeWithTheKeyboardUp,
    ) {
        view = LocalView.current
        Box(Modifier.fillMaxSize()) {
            ConversationScreen(
                ConversationUiState.Success("bob", messages, HapticIcon.PRESETS, HapticIcon.STROKE, null, PeerFeel(RendererKind.AMPLITUDE_WAVEFORM, 93), null),
                ConversationActions(), clock, now,
            )
            KeyboardStandIn(Modifier.align(Alignment.BottomCenter))
        }
    }

    private companion object {
        const val KEYBOARD_DP = 300
    }
}

/** A drawn stand-in for the on-screen keyboard, in the space its insets take; not part of the app. */
@Composable
private fun KeyboardStandIn(modifier: Modifier) {
    val rows = listOf("qwertyuiop", "asdfghjkl", "zxcvbnm")
    // Fixed size: the keyboard is the system's and does not follow the app's font scale.
    val keySize = with(LocalDensity.current) { 18.dp.toSp() }
    Column(
        modifier.fillMaxWidth().windowInsetsBottomHeight(WindowInsets.ime).background(Color(0xFFE3E3E8)).clearAndSetSemantics {}
            .padding(6.dp),
        verticalArrangement = Arrangement.spacedBy(8.dp, Alignment.CenterVertically),
    ) {
        for (row in rows) {
            Row(Modifier.fillMaxWidth(), horizontalArrangement = Arrangement.spacedBy(4.dp, Alignment.CenterHorizontally)) {
                for (key in row) {
                    Box(Modifier.weight(1f, fill = false).height(44.dp).background(Color.White, RoundedCornerShape(6.dp)), contentAlignment = Alignment.Center) {
                        Text(key.toString(), Modifier.padding(horizontal = 9.dp), fontSize = keySize, color = Color(0xFF1B1B1F), textAlign = TextAlign.Center)
                    }
                }
            }
        }
        Box(Modifier.fillMaxWidth().padding(horizontal = 60.dp).height(44.dp).background(Color.White, RoundedCornerShape(6.dp)))
    }
}
