package org.hapticon.app.screenshots

import android.Manifest
import android.app.Application
import android.app.Notification
import android.app.NotificationManager
import android.content.Context
import android.graphics.drawable.Icon
import android.widget.FrameLayout
import androidx.compose.foundation.background
import androidx.compose.foundation.layout.Column
import androidx.compose.foundation.layout.fillMaxSize
import androidx.compose.foundation.layout.fillMaxWidth
import androidx.compose.foundation.layout.padding
import androidx.compose.foundation.shape.RoundedCornerShape
import androidx.compose.ui.Modifier
import androidx.compose.ui.draw.clip
import androidx.compose.ui.graphics.Color
import androidx.compose.ui.unit.dp
import androidx.compose.ui.viewinterop.AndroidView
import androidx.test.core.app.ApplicationProvider
import org.hapticon.app.sync.MessageNotifier
import org.hapticon.core.HapticIcon
import org.hapticon.messaging.ArrivalAlert
import org.hapticon.messaging.ChatMessage
import org.junit.Assert.assertEquals
import org.junit.Test
import org.robolectric.Shadows.shadowOf
import org.robolectric.annotation.Config
import org.robolectric.shadows.ShadowSystem

/**
 * bob's message notification as the shade shows it: the notification [MessageNotifier] posts, recovered by Android's
 * own `Notification.Builder.recoverBuilder` and inflated from the platform's own templates (`RemoteViews.apply`, the
 * MessagingStyle layouts of the Robolectric runtime's framework, in the conversation layout SystemUI chooses for a
 * conversation), collapsed and expanded, on a dark shade. What SystemUI adds around it (the shade's chrome, the
 * Conversations header, the heads-up frame) is not drawn: Robolectric has no SystemUI.
 */
// Only as tall as the two notifications: a shade, not a whole screen.
@Config(qualifiers = "w411dp-h360dp-xxhdpi")
class NotificationShadeScreenshotTest : ScreenshotTest() {
    private val context = ApplicationProvider.getApplicationContext<Context>()

    private fun postedByBob(): Notification {
        shadowOf(context as Application).grantPermissions(Manifest.permission.POST_NOTIFICATIONS)
        // The framework's clock under Robolectric (frozen, just after 1970), which the shade draws every time against: the
        // conversation layout shows the latest line's time, so bob's lines were sent 2 minutes and just before it.
        shadowOf(android.os.Looper.getMainLooper()).idleFor(java.time.Duration.ofMinutes(3)) // room for lines before now
        val now = ShadowSystem.currentTimeMillis()
        val notifier = MessageNotifier(context, now = { now }) { "alice" }
        notifier.show(ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c01", "bob", now - 120_000, "feel this", icon = HapticIcon.KNOCK), ArrivalAlert.ICON)
        // The override (U+202E) a hostile peer might send is neutralised before it reaches the shade.
        notifier.show(ChatMessage("0b7e7c1e-3f7b-4a57-9d3e-2f1c5a6b7c02", "bob", now - 5_000, "and a hug \u202Efor you", icon = HapticIcon.HUG), ArrivalAlert.ICON)
        return shadowOf(context.getSystemService(NotificationManager::class.java)).getNotification("bob", MessageNotifier.NOTIFICATION_ID)
    }

    // A picture of Android's own notification views inside an AndroidView, which the checks (Compose semantics) cannot see.
    @Test
    fun shade_bobsConversationNotification() {
        val notification = postedByBob()
        assertEquals("icons-bob", notification.channelId)
        screen("notification-shade", listOf(Variant.Light), accessibility = false) {
            Column(Modifier.fillMaxSize().background(Color(0xFF1B1B1F)).padding(horizontal = 12.dp, vertical = 24.dp)) {
                for (expanded in listOf(false, true)) {
                    AndroidView(
                        factory = { ctx ->
                            val builder = Notification.Builder.recoverBuilder(ctx, notification)
                            // What SystemUI's ConversationNotificationProcessor does for a notification with a valid
                            // conversation shortcut: the conversation layout (hidden API, CONVERSATION_TYPE_NORMAL = 1).
                            Notification.MessagingStyle::class.java.getMethod("setConversationType", Int::class.java)
                                .invoke(builder.style, 1)
                            // ...and the shortcut's icon, which it reads from LauncherApps.getShortcutIcon.
                            Notification.MessagingStyle::class.java.getMethod("setShortcutIcon", Icon::class.java)
                                .invoke(builder.style, Icon.createWithAdaptiveBitmap(MessageNotifier.avatarOf("bob")))
                            val views = if (expanded) builder.createBigContentView() else builder.createContentView()
                            views.apply(ctx, FrameLayout(ctx))
                        },
                        modifier = Modifier.fillMaxWidth().padding(bottom = 12.dp).clip(RoundedCornerShape(24.dp)).background(Color(0xFFF2F0F4)),
                    )
                }
            }
        }
    }
}
