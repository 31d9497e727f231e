package org.hapticon.app.feature.chat

import android.graphics.Bitmap
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Surface
import androidx.compose.runtime.Composable
import androidx.compose.ui.graphics.ImageBitmap
import androidx.compose.ui.graphics.asAndroidBitmap
import androidx.compose.ui.graphics.toArgb
import androidx.compose.ui.test.captureToImage
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onRoot
import java.io.File
import java.time.ZoneOffset
import java.util.Locale
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.designsystem.HapticonSeed
import org.hapticon.app.designsystem.HapticonTheme
import org.hapticon.app.designsystem.seedColorScheme
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.hapticon.messaging.InviteLink
import org.hapticon.messaging.RendererKind
import org.hapticon.messaging.mqtt.BrokerAddress
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.annotation.Config
import org.robolectric.annotation.GraphicsMode

/**
 * The chat screens rendered as a phone shows them (Robolectric native graphics, 411×891 dp at xxhdpi),
 * in Hapticon's own light and dark schemes (dynamic colour off). Each test checks pixels that must hold
 * (own bubbles on the right in primaryContainer, the theme's background) and writes the PNG to
 * `$HAPTICON_SCREENSHOTS_DIR` when set (docs/images/screens/ for the docs), else to a temporary folder.
 */
@RunWith(RobolectricTestRunner::class)
@GraphicsMode(GraphicsMode.Mode.NATIVE)
@Config(sdk = [35], qualifiers = "w411dp-h891dp-xxhdpi")
class ChatScreenshotTest {
    @get:Rule
    val compose = createComposeRule()

    private val now = 1_767_225_600_000L + 15 * 3_600_000L + 42 * 60_000L // 2026-01-01 15:42 UTC
    private val clock = ChatClock(ZoneOffset.UTC, Locale.UK)
    private val out: File = System.getenv("HAPTICON_SCREENSHOTS_DIR")?.let(::File)
        ?: File(System.getProperty("java.io.tmpdir"), "hapticon-screens")

    private fun shoot(name: String, dark: Boolean, content: @Composable () -> Unit): Bitmap {
        compose.setContent {
            HapticonTheme(darkTheme = dark, dynamicColor = false) {
                Surface(color = MaterialTheme.colorScheme.surface) { content() }
            }
        }
        compose.waitForIdle()
        val image: ImageBitmap = compose.onRoot().captureToImage()
        val bitmap = image.asAndroidBitmap()
        out.mkdirs()
        File(out, "chats-$name-${if (dark) "dark" else "light"}.png").outputStream().use { bitmap.compress(Bitmap.CompressFormat.PNG, 100, it) }
        return bitmap
    }

    private fun message(n: Int, outgoing: Boolean, state: MessageState, at: Long, text: String, icon: HapticIcon? = null, sticker: String? = null) =
        StoredMessage("0b7e7c1e-3f7b-4a57-9d3e-%012d".format(n), "bob", if (outgoing) "alice" else "bob", at, text, sticker, icon, outgoing, state, null)

    private val day = 86_400_000L
    private val conversation = listOf(
        message(1, false, MessageState.RECEIVED, now - day - 3_600_000, "Did the study session go well?"),
        message(2, true, MessageState.READ, now - day - 3_500_000, "Yes, very"),
        message(3, false, MessageState.RECEIVED, now - 50 * 60_000, "Try this one", HapticIcon.HUG),
        message(4, true, MessageState.FELT, now - 40 * 60_000, "Felt it! Back to you", HapticIcon.STROKE),
        message(5, true, MessageState.READ, now - 30 * 60_000, "Lovely"),
        message(6, true, MessageState.DELIVERED, now - 20 * 60_000, "Knock knock", HapticIcon.KNOCK),
        message(7, true, MessageState.SENT, now - 10 * 60_000, "Are you there?"),
        message(8, true, MessageState.FAILED, now - 5 * 60_000, "Sent while offline"),
        message(9, true, MessageState.SENDING, now - 60_000, "And one more"),
    )

    private fun conversationState() = ConversationUiState.Success(
        "bob", conversation, HapticIcon.PRESETS, HapticIcon.KNOCK, null, PeerFeel(RendererKind.AMPLITUDE_WAVEFORM, 93), null,
    )

    private val list = ChatListUiState.Success(
        "alice",
        listOf(
            ConversationSummary("bob", "And one more", now - 60_000, 0, IconJson.encode(HapticIcon.HIT), lastOutgoing = true),
            ConversationSummary("carol.lee", "Can you feel the difference?", now - 25 * 60_000, 3, IconJson.encode(HapticIcon.STROKE)),
            ConversationSummary("participant-07", "", now - 5 * 3_600_000, 1, IconJson.encode(HapticIcon.HUG)),
            ConversationSummary("dana", "See you at the lab", now - 2 * day, 0, lastOutgoing = true),
            ConversationSummary("lab_pi", "Protocol v2 is ready", now - 9 * day, 0),
        ),
    )

    private fun conversationShot(dark: Boolean) {
        val bitmap = shoot("conversation", dark) { ConversationScreen(conversationState(), ConversationActions(), clock, now) }
        val scheme = seedColorScheme(HapticonSeed, dark)
        // Own bubbles fill primaryContainer on the right; received ones never reach the right edge region.
        val w = bitmap.width
        var ownRight = 0
        var ownLeft = 0
        for (y in 0 until bitmap.height step 4) {
            if (bitmap.getPixel(w - 60, y) == scheme.primaryContainer.toArgb()) ownRight++
            if (bitmap.getPixel(60, y) == scheme.primaryContainer.toArgb()) ownLeft++
        }
        assertTrue("own bubbles on the right: $ownRight rows", ownRight > 50)
        assertEquals("no own bubble on the left", 0, ownLeft)
    }

    @Test
    fun conversation_light() = conversationShot(dark = false)

    @Test
    fun conversation_dark() = conversationShot(dark = true)

    private fun listShot(dark: Boolean) {
        val bitmap = shoot("list", dark) { ChatListScreen(list, ChatListActions(), clock, now) }
        assertEquals(seedColorScheme(HapticonSeed, dark).surface.toArgb(), bitmap.getPixel(bitmap.width / 2, bitmap.height - 10))
    }

    @Test
    fun list_light() = listShot(dark = false)

    @Test
    fun list_dark() = listShot(dark = true)

    @Test
    fun emptyList_light() {
        shoot("empty", dark = false) { ChatListScreen(ChatListUiState.Success("alice", emptyList()), ChatListActions(), clock, now) }
    }

    @Test
    fun firstLaunch_light() {
        shoot("first-launch", dark = false) { FirstLaunchScreen("", AccountCheck.Failed("No answer from tcp://192.168.1.20:1883 within 5 s. Is `hapticon broker` running, and is this phone on the same network?")) { _, _ -> } }
    }

    @Test
    fun firstLaunch_dark() {
        shoot("first-launch", dark = true) { FirstLaunchScreen("", AccountCheck.Idle) { _, _ -> } }
    }

    private fun inviteShot(dark: Boolean) {
        val bitmap = shoot("invite", dark) {
            InviteScreen(InviteLink("alice", BrokerAddress("192.168.1.20", 1883)), onBack = {}, onShare = {})
        }
        // The code is black on white in both themes (scanners need dark on light).
        var black = 0
        for (x in 0 until bitmap.width step 3) if (bitmap.getPixel(x, bitmap.height / 2 - 100) == android.graphics.Color.BLACK) black++
        assertTrue("QR modules drawn: $black", black > 10)
    }

    @Test
    fun invite_light() = inviteShot(dark = false)

    @Test
    fun invite_dark() = inviteShot(dark = true)

    private fun settingsShot(dark: Boolean) {
        shoot("settings", dark) {
            SettingsScreen(
                SettingsUiState(
                    ChatPreferences(userName = "alice", brokerUrl = "tcp://192.168.1.20:1883", autoPlay = true, stayReachable = true),
                    listOf(RendererKind.AMPLITUDE_WAVEFORM, RendererKind.ON_OFF), "connected",
                ),
                SettingsActions(), version = "0.1",
            )
        }
    }

    @Test
    fun settings_light() = settingsShot(dark = false)

    @Test
    fun settings_dark() = settingsShot(dark = true)
}
