package org.hapticon.app.feature.chat

import android.Manifest
import org.hapticon.app.playback.usageVibrator
import android.app.Application
import android.app.NotificationManager
import android.content.Context
import android.os.Vibrator
import androidx.compose.runtime.getValue
import androidx.compose.runtime.mutableStateOf
import androidx.compose.runtime.setValue
import androidx.compose.ui.test.assertIsDisplayed
import androidx.compose.ui.test.junit4.createComposeRule
import androidx.compose.ui.test.onNodeWithContentDescription
import androidx.compose.ui.test.onNodeWithText
import androidx.compose.ui.test.performClick
import androidx.compose.ui.test.performScrollTo
import androidx.room.Room
import androidx.test.core.app.ApplicationProvider
import kotlinx.coroutines.CoroutineScope
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.SupervisorJob
import kotlinx.coroutines.cancelAndJoin
import kotlinx.coroutines.flow.first
import kotlinx.coroutines.runBlocking
import kotlinx.coroutines.withTimeout
import org.hapticon.app.data.ChatPreferences
import org.hapticon.app.data.InMemoryChatSettings
import org.hapticon.app.data.OfflineFirstChatRepository
import org.hapticon.app.data.database.HapticonDatabase
import org.hapticon.app.playback.AdaptiveHapticPlayer
import org.hapticon.app.playback.DeviceCapabilities
import org.hapticon.app.playback.RendererChoice
import org.hapticon.app.sync.ChatSync
import org.hapticon.app.sync.MessageNotifier
import org.hapticon.app.sync.TestMessenger
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.Clock
import org.hapticon.messaging.ConnectionState
import org.hapticon.messaging.InboxEvent
import org.hapticon.messaging.VibrationRateLimiter
import org.junit.After
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Rule
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config

/**
 * The user refused notifications (Android 13+): a message that arrives is announced nowhere, yet it is
 * stored and waits in the chat list with its unread badge, and Settings says that notifications are off
 * with a way to turn them on.
 */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35], qualifiers = "w400dp-h1600dp")
class NotificationsRefusedTest {
    @get:Rule
    val compose = createComposeRule()

    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val scope = CoroutineScope(SupervisorJob() + Dispatchers.Default)
    private val db = Room.inMemoryDatabaseBuilder(context, HapticonDatabase::class.java).build()
    private val repository = OfflineFirstChatRepository(db)

    @After
    fun tearDown() {
        runBlocking { scope.coroutineContext[kotlinx.coroutines.Job]!!.cancelAndJoin() }
        db.close()
    }

    @Test
    fun messageWhilePermissionRefused_nothingPostedButStoredAndShownUnread_settingsSayWhy() {
        shadowOf(context as Application).denyPermissions(Manifest.permission.POST_NOTIFICATIONS)
        val device = DeviceCapabilities(hasVibrator = true, hasAmplitudeControl = true, apiLevel = 35)
        val messenger = TestMessenger("alice")
        val settings = InMemoryChatSettings(ChatPreferences(userName = "alice", brokerUrl = "tcp://192.168.1.20:1883"))
        val sync = ChatSync(
            repository, repository, settings, { _, _, _ -> messenger },
            AdaptiveHapticPlayer(usageVibrator(context.getSystemService(Vibrator::class.java)), { device }, { null }), VibrationRateLimiter(Clock.MONOTONIC),
            { user -> RendererChoice.capabilitiesOf(user, device, null) }, scope,
        )
        val notifier = MessageNotifier(context) { "alice" }
        val announced = mutableListOf<Boolean>()
        sync.onIncoming = { message, _ -> announced += notifier.show(message) }
        sync.start()
        runBlocking { withTimeout(5_000) { messenger.state.first { it == ConnectionState.Connected } } }

        messenger.deliver(InboxEvent.MessageReceived(ChatMessage.compose("bob", "are you there?", null, HapticIcon.KNOCK, Clock.SYSTEM)))

        // Nothing announced: the notifier knew it could not, and Android holds no notification.
        assertFalse(notifier.canNotify())
        assertEquals(listOf(false), announced)
        assertEquals(0, shadowOf(context.getSystemService(NotificationManager::class.java)).allNotifications.size)
        // Nothing lost: the message is stored, unread, and the list shows it with its badge.
        val conversations = runBlocking { repository.conversations().first() }
        assertEquals(listOf(Triple("bob", "are you there?", 1)), conversations.map { Triple(it.peer, it.lastText, it.unread) })

        var onSettings by mutableStateOf(false)
        var opened = 0
        compose.setContent {
            if (!onSettings) {
                ChatListScreen(ChatListUiState.Success("alice", conversations), ChatListActions())
            } else {
                SettingsScreen(
                    SettingsUiState(settings.preferences.value, emptyList(), "connected", notificationsAllowed = notifier.canNotify()),
                    SettingsActions(onAllowNotifications = { opened++ }),
                )
            }
        }
        compose.onNodeWithText("〰 knock · are you there?").assertIsDisplayed()
        compose.onNodeWithContentDescription("1 unread", useUnmergedTree = true).assertIsDisplayed()

        onSettings = true
        compose.onNodeWithText(NOTIFICATIONS_OFF).performScrollTo().assertIsDisplayed()
        compose.onNodeWithText("Allow notifications").performScrollTo().performClick()
        assertEquals(1, opened)
    }

    @Test
    fun settings_notificationsAllowed_sayNothingAboutThem() {
        compose.setContent { SettingsScreen(SettingsUiState(ChatPreferences(userName = "alice"), emptyList(), "connected"), SettingsActions()) }
        compose.onNodeWithText(NOTIFICATIONS_OFF).assertDoesNotExist()
        compose.onNodeWithText("Allow notifications").assertDoesNotExist()
    }
}
