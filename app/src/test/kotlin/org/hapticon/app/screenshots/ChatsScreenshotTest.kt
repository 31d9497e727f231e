package org.hapticon.app.screenshots

import androidx.compose.ui.graphics.asAndroidBitmap
import androidx.compose.ui.graphics.toArgb
import androidx.compose.ui.test.captureToImage
import androidx.compose.ui.test.onRoot
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.ClientCertificateStatus
import org.hapticon.app.data.database.ConversationSummary
import org.hapticon.app.data.database.MessageState
import org.hapticon.app.data.database.StoredMessage
import org.hapticon.app.designsystem.HapticonSeed
import org.hapticon.app.designsystem.seedColorScheme
import org.hapticon.app.feature.chat.AccountCheck
import org.hapticon.app.feature.chat.ChatClock
import org.hapticon.app.feature.chat.ChatConnection
import org.hapticon.app.feature.chat.ChatListActions
import org.hapticon.app.feature.chat.ChatListScreen
import org.hapticon.app.feature.chat.ChatListUiState
import org.hapticon.app.feature.chat.ConversationActions
import org.hapticon.app.feature.chat.ConversationScreen
import org.hapticon.app.feature.chat.ConversationUiState
import org.hapticon.app.feature.chat.FirstLaunchScreen
import org.hapticon.app.feature.chat.InviteScreen
import org.hapticon.app.feature.chat.NewChatProblem
import org.hapticon.app.feature.chat.PeerFeel
import org.hapticon.app.feature.chat.SettingsActions
import org.hapticon.app.feature.chat.SettingsScreen
import org.hapticon.app.feature.chat.SettingsUiState
import org.hapticon.core.HapticIcon
import org.hapticon.core.io.IconJson
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.BrokerAddress
import org.hapticon.messaging.InviteLink
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import java.time.ZoneOffset
import java.util.Locale

/**
 * The Chats tab's screens in light and dark (docs/app-tour.md, "Chats"): first launch, the chat list
 * (and empty), a conversation with every message state, the invite and Settings. The main ones (the list,
 * the conversation, Settings) also at the largest font scale. A fixed clock, zone
 * and locale keep every time on them the same from run to run.
 */
class ChatsScreenshotTest : ScreenshotTest() {
    private val now = 1_767_225_600_000L + 15 * 3_600_000L + 42 * 60_000L // 2026-01-01 15:42 UTC
    private val day = 86_400_000L
    private val clock = ChatClock(ZoneOffset.UTC, Locale.UK)

    private fun message(n: Int, outgoing: Boolean, state: MessageState, at: Long, text: String, icon: HapticIcon? = null) =
        StoredMessage("0b7e7c1e-3f7b-4a57-9d3e-%012d".format(n), "bob", if (outgoing) "alice" else "bob", at, text, null, icon, outgoing, state, null)

    private val conversation = listOf(
        message(1, false, MessageState.RECEIVED, now - day - 3_600_000, "Did the study session go well?"),
        message(2, true, MessageState.READ, now - day - 3_500_000, "Yes, very"),
        message(3, false, MessageState.RECEIVED, now - 50 * 60_000, "Try this one", HapticIcon.HUG),
        message(4, true, MessageState.FELT, now - 40 * 60_000, "Felt it! Back to you", HapticIcon.STROKE),
        message(5, true, MessageState.READ, now - 30 * 60_000, "Lovely"),
        message(6, true, MessageState.DELIVERED, now - 20 * 60_000, "Knock knock"),
        message(7, true, MessageState.SENT, now - 10 * 60_000, "Are you there?"),
        message(8, true, MessageState.FAILED, now - 5 * 60_000, "Sent while offline"),
        message(9, true, MessageState.SENDING, now - 60_000, "And one more"),
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

    @Test
    fun conversation_everyState_ownOnTheRightInPrimaryContainer() {
        // Dark last, so the check below reads the dark rendering; the largest font scale is a main-screen variant.
        screen("chats-conversation", variants = listOf(Variant.Light, Variant.LargestFont, Variant.Dark)) {
            ConversationScreen(
                ConversationUiState.Success("bob", conversation, HapticIcon.PRESETS, HapticIcon.KNOCK, null, PeerFeel(RendererKind.AMPLITUDE_WAVEFORM, 93), null),
                ConversationActions(), clock, now,
            )
        }
        // The last variant drawn is dark: own bubbles fill its primaryContainer on the right, never on the left.
        val bitmap = compose.onRoot().captureToImage().asAndroidBitmap()
        val own = seedColorScheme(HapticonSeed, dark = true).primaryContainer.toArgb()
        val rows = 0 until bitmap.height step 4
        assertTrue(rows.count { bitmap.getPixel(bitmap.width - 60, it) == own } > 50)
        assertEquals(0, rows.count { bitmap.getPixel(60, it) == own })
    }

    @Test
    fun list_badgesTimesAndPreviews() = screen("chats-list", variants = Variant.MAIN) { ChatListScreen(list, ChatListActions(), clock, now) }

    /** Offline: the list is there as always (from Room), with one line under the top bar saying why nothing moves. */
    @Test
    fun list_offline_saysSoAndShowsTheChats() = screen("chats-list-offline") {
        ChatListScreen(list.copy(connection = ChatConnection.Offline), ChatListActions(), clock, now)
    }

    /** The broker does not answer: the line names it. */
    @Test
    fun list_brokerUnreachable_saysWhichBroker() = screen("chats-list-unreachable", variants = listOf(Variant.Light)) {
        ChatListScreen(list.copy(connection = ChatConnection.Unreachable("192.168.1.20:1883")), ChatListActions(), clock, now)
    }

    /** A conversation with someone who never connected to the broker: the line says why the message keeps one tick. */
    @Test
    fun conversation_peerNeverConnected_saysSo() = screen("chats-conversation-never-connected", variants = listOf(Variant.Light)) {
        ConversationScreen(
            ConversationUiState.Success(
                "caroll", listOf(message(1, true, MessageState.SENT, now - 2 * 60_000, "Hi Carol, it's Alice from the lab").copy(conversation = "caroll")),
                HapticIcon.PRESETS, null, null, null, null, peerNeverConnected = true,
            ),
            ConversationActions(), clock, now,
        )
    }

    @Test
    fun list_empty_saysWhatToDoFirst() = screen("chats-empty") {
        ChatListScreen(ChatListUiState.Success("alice", emptyList()), ChatListActions(), clock, now)
    }

    @Test
    fun firstLaunch_failedTest_saysWhy() = screen("chats-first-launch") {
        FirstLaunchScreen(
            "", AccountCheck.Failed("No answer from tcp://192.168.1.20:1883 within 5 s. Is the broker running on the study computer, and is this phone on the same network?"),
            onSave = { _, _, _ -> },
        )
    }

    @Test
    fun invite_qrCodeAndLink() = screen("chats-invite") {
        InviteScreen(InviteLink("alice", BrokerAddress("192.168.1.20", 1883)), onBack = {}, onShare = {})
    }

    @Test
    fun settings_everythingOutOfTheList() = screen("chats-settings", variants = Variant.MAIN) {
        SettingsScreen(
            SettingsUiState(
                ChatPreferences(userName = "alice", brokerUrl = "tcp://192.168.1.20:1883", autoPlay = true, stayReachable = true),
                listOf(RendererKind.AMPLITUDE_WAVEFORM, RendererKind.ON_OFF), "connected",
            ),
            SettingsActions(), version = "0.1",
        )
    }

    @Test
    fun settings_notificationsRefused_saysWhatStillWorksAndHowToAllow() = screen("chats-settings-notifications-off") {
        SettingsScreen(
            SettingsUiState(
                ChatPreferences(userName = "alice", brokerUrl = "tcp://192.168.1.20:1883", autoPlay = true, stayReachable = true),
                listOf(RendererKind.AMPLITUDE_WAVEFORM, RendererKind.ON_OFF), "connected", notificationsAllowed = false,
            ),
            SettingsActions(), version = "0.1",
        )
    }

    @Test
    fun settings_clientCertificateInUse() = screen("chats-settings-certificate") {
        SettingsScreen(
            SettingsUiState(
                ChatPreferences(userName = "p01", brokerUrl = "ssl://192.168.1.20:8883"),
                listOf(RendererKind.AMPLITUDE_WAVEFORM, RendererKind.ON_OFF), "connected",
                clientCertificate = ClientCertificateStatus.InUse("p01", java.time.Instant.parse("2027-11-26T10:00:00Z"), "Hapticon study 7"),
            ),
            SettingsActions(), version = "0.1",
        )
    }

    @Test
    fun settings_clientCertificatePassword_wrongOneSaysSo() = screen("chats-settings-certificate-password") {
        SettingsScreen(
            SettingsUiState(
                ChatPreferences(userName = "p01", brokerUrl = "ssl://192.168.1.20:8883"),
                listOf(RendererKind.AMPLITUDE_WAVEFORM, RendererKind.ON_OFF), "connecting",
                certificateImport = org.hapticon.app.feature.chat.CertificateImport(
                    "p01.p12", "the client certificate cannot be opened: wrong password, or not a PKCS#12 (.p12) file",
                ),
            ),
            SettingsActions(), version = "0.1",
        )
    }
}
