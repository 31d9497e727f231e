package org.hapticon.app.sync

import android.Manifest
import android.app.Application
import android.app.Notification
import android.app.NotificationChannel
import android.app.NotificationManager
import android.content.Context
import android.content.pm.ShortcutInfo
import android.content.pm.ShortcutManager
import android.media.AudioManager
import android.provider.Settings
import androidx.core.app.NotificationCompat
import androidx.test.core.app.ApplicationProvider
import org.hapticon.app.MainActivity
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.AlertChannel
import org.hapticon.messaging.ArrivalAlert
import org.hapticon.messaging.ChannelSettings
import org.hapticon.messaging.ChatMessage
import org.hapticon.messaging.DoNotDisturb
import org.hapticon.messaging.RingerMode
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNotNull
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Before
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config
import org.robolectric.annotation.GraphicsMode

/** The message notification as Android receives it: channels, the conversation (shortcut, person, locus), the lines. */
@RunWith(RobolectricTestRunner::class)
@Config(sdk = [35])
@GraphicsMode(GraphicsMode.Mode.NATIVE) // the avatar is drawn
class MessageNotifierTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()
    private val system = context.getSystemService(NotificationManager::class.java)
    private val notifier = MessageNotifier(context) { "alice" }
    private val knock = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8d", "bob", 1_767_225_600_000, "feel this", icon = HapticIcon.KNOCK)

    @Before
    fun setUp() {
        shadowOf(context as Application).grantPermissions(Manifest.permission.POST_NOTIFICATIONS)
    }

    private fun posted(): Notification = shadowOf(system).getNotification("bob", MessageNotifier.NOTIFICATION_ID)

    @Test
    fun iconThatPlays_postedOnAChannelThatNeitherRingsNorVibrates() {
        assertTrue(notifier.show(knock, ArrivalAlert.ICON))

        assertEquals("icons-bob", posted().channelId)
        val channel = system.getNotificationChannel("icons-bob")
        assertEquals(NotificationManager.IMPORTANCE_HIGH, channel.importance)
        assertFalse(channel.shouldVibrate())
        assertNull(channel.vibrationPattern)
        // No sound either: in vibrate mode Android would demote it to its fallback vibration over the icon.
        assertNull(channel.sound)
        assertEquals("bob · haptic icons", channel.name)
        assertEquals(MessageNotifier.GROUP, channel.group)
    }

    @Test
    fun messageWhoseIconDoesNotPlay_postedOnTheRingingVibratingMessageChannel() {
        val text = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8e", "bob", 1_767_225_600_000, "are you there?")
        assertTrue(notifier.show(text, ArrivalAlert.NOTIFICATION))

        assertEquals("chat-bob", posted().channelId)
        val channel = system.getNotificationChannel("chat-bob")
        assertEquals(NotificationManager.IMPORTANCE_HIGH, channel.importance)
        assertTrue(channel.shouldVibrate())
        assertEquals(Settings.System.DEFAULT_NOTIFICATION_URI, channel.sound)
        assertEquals("bob", channel.name)
    }

    @Test
    fun quietIcon_postedOnTheIconChannel() {
        notifier.show(knock, ArrivalAlert.QUIET)
        assertEquals(MessageNotifier.channelId("bob", AlertChannel.ICONS), posted().channelId)
    }

    @Test
    fun notification_isAConversation_withItsLongLivedShortcutPersonAndLocus() {
        notifier.show(knock, ArrivalAlert.ICON)
        val notification = posted()

        assertEquals("chat-bob", notification.shortcutId)
        assertEquals("chat-bob", notification.locusId!!.id)
        assertEquals(Notification.CATEGORY_MESSAGE, notification.category)
        val style = NotificationCompat.MessagingStyle.extractMessagingStyleFromNotification(notification)!!
        assertFalse(style.isGroupConversation)
        val bob = style.messages.single().person!!
        assertEquals("bob", bob.name.toString())
        assertNotNull("the person has an avatar", bob.icon)

        val shortcut = context.getSystemService(ShortcutManager::class.java).dynamicShortcuts.single()
        assertEquals("chat-bob", shortcut.id)
        assertEquals("bob", shortcut.shortLabel.toString())
        assertEquals("chat-bob", shortcut.locusId!!.id)
        // What AOSP ShortcutHelper.isConversationShortcut checks: long-lived and enabled (isLongLived is hidden API).
        assertTrue(ShortcutInfo::class.java.getMethod("isLongLived").invoke(shortcut) as Boolean)
        assertTrue(shortcut.isEnabled)
        // A sharing shortcut: its category is the manifest's share target's (ShareToChatTest reads that).
        assertEquals(setOf(MessageNotifier.SHORTCUT_CATEGORY), shortcut.categories)
        assertEquals(MessageNotifier.ACTION_OPEN_CHAT, shortcut.intent!!.action)
        assertEquals("bob", shortcut.intent!!.getStringExtra(MessageNotifier.EXTRA_PEER))
    }

    @Test
    fun tap_opensThatChat() {
        notifier.show(knock, ArrivalAlert.ICON)

        val opened = shadowOf(posted().contentIntent).savedIntent
        assertEquals(MainActivity::class.java.name, opened.component!!.className)
        assertEquals(MessageNotifier.ACTION_OPEN_CHAT, opened.action)
        assertEquals("bob", opened.getStringExtra(MessageNotifier.EXTRA_PEER))
    }

    @Test
    fun peerText_neutralisedInTheShade() {
        val hostile = ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c8f", "bob", 1_767_225_600_000, "invoice\u202Efdp.exe\u0007\r\nnow")
        notifier.show(hostile, ArrivalAlert.NOTIFICATION)

        val style = NotificationCompat.MessagingStyle.extractMessagingStyleFromNotification(posted())!!
        assertEquals("invoicefdp.exe\nnow", style.messages.single().text.toString())
    }

    @Test
    fun arrivalConditions_readTheRingerDoNotDisturbAndTheIconChannel() {
        assertEquals(RingerMode.NORMAL, notifier.arrivalConditions("bob").ringer)
        assertEquals(DoNotDisturb.OFF, notifier.arrivalConditions("bob").doNotDisturb)
        assertEquals(ChannelSettings(alerting = true, conversation = true), notifier.arrivalConditions("bob").iconChannel)

        context.getSystemService(AudioManager::class.java).ringerMode = AudioManager.RINGER_MODE_SILENT
        assertEquals(RingerMode.SILENT, notifier.arrivalConditions("bob").ringer)

        // Priority only, messages from anyone, priority conversations.
        shadowOf(system).setNotificationPolicyAccessGranted(true)
        system.notificationPolicy = NotificationManager.Policy(
            NotificationManager.Policy.PRIORITY_CATEGORY_MESSAGES or NotificationManager.Policy.PRIORITY_CATEGORY_CONVERSATIONS,
            0, NotificationManager.Policy.PRIORITY_SENDERS_ANY, 0, NotificationManager.Policy.CONVERSATION_SENDERS_IMPORTANT,
        )
        system.setInterruptionFilter(NotificationManager.INTERRUPTION_FILTER_PRIORITY)
        assertEquals(
            DoNotDisturb(DoNotDisturb.Filter.PRIORITY, DoNotDisturb.Senders.ANYONE, DoNotDisturb.ConversationSenders.IMPORTANT),
            notifier.arrivalConditions("bob").doNotDisturb,
        )
        system.setInterruptionFilter(NotificationManager.INTERRUPTION_FILTER_NONE)
        assertEquals(DoNotDisturb.Filter.NONE, notifier.arrivalConditions("bob").doNotDisturb.filter)
    }

    @Test
    fun conversationSilencedByTheUser_itsIconChannelDoesNotAlert() {
        assertTrue(notifier.iconChannelSettings("bob").alerting)
        // Android's own channel for the conversation, made when the user changes its settings ("Silent").
        val silenced = NotificationChannel("icons-bob:chat-bob", "bob", NotificationManager.IMPORTANCE_LOW).apply {
            setConversationId("icons-bob", "chat-bob")
        }
        system.createNotificationChannel(silenced)
        assertEquals(ChannelSettings(alerting = false, conversation = true), notifier.iconChannelSettings("bob"))
    }

    @Test
    fun avatar_isTheInitialOnAColourOfTheName() {
        val avatar = MessageNotifier.avatarOf("bob")
        assertEquals(216, avatar.width)
        // The corner carries the background colour, the same for the same name; bob's is the name's pick of eight.
        assertEquals(0xFFAD1457.toInt(), avatar.getPixel(0, 0))
        assertEquals(avatar.getPixel(0, 0), MessageNotifier.avatarOf("bob").getPixel(0, 0))
        // The notification's disc: transparent corners, the colour at the rim, the white letter at the centre.
        val disc = MessageNotifier.avatarOf("bob", round = true)
        assertEquals(0, android.graphics.Color.alpha(disc.getPixel(0, 0)))
        assertEquals(0xFFAD1457.toInt(), disc.getPixel(108, 4))
    }

    @Test
    fun personIcon_isDrawnNoLargerThanAndroidKeepsIt_soBuildScalesNothing() {
        val limit = android.content.res.Resources.getSystem().let {
            it.getDimensionPixelSize(it.getIdentifier("notification_person_icon_max_size", "dimen", "android"))
        }
        assertEquals(limit, notifier.personIconPx)
        // This phone keeps 144 px: the disc is drawn at that size, below the 216 px of the adaptive icon.
        assertEquals(144, limit)
        val drawn = notifier.personOf("bob").icon!!.loadDrawable(context) as android.graphics.drawable.BitmapDrawable
        assertEquals(144, drawn.bitmap.width)
    }
}
