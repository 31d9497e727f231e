package org.hapticon.app.screenshots

import java.time.ZoneOffset
import java.util.Locale
import org.hapticon.app.feature.chat.AccountCheck
import org.hapticon.app.feature.chat.ChatClock
import org.hapticon.app.feature.chat.ChatListActions
import org.hapticon.app.feature.chat.ChatListScreen
import org.hapticon.app.feature.chat.ChatListUiState
import org.hapticon.app.feature.chat.FirstLaunchScreen
import org.hapticon.app.feature.chat.ReachableNote
import org.hapticon.app.feature.chat.ReachableOfferScreen
import androidx.compose.foundation.layout.padding
import androidx.compose.runtime.remember
import androidx.compose.ui.graphics.asImageBitmap
import androidx.compose.ui.unit.dp
import androidx.core.graphics.drawable.toBitmap
import org.junit.Test
import org.robolectric.annotation.Config

/**
 * First launch on the narrowest common phone (360 dp wide) in light, dark and at font scale 2.0: the welcome form
 * and the offer of "Stay reachable" and autoplay that follows a passed connection test; and the chat list's note
 * when the user said "Not now".
 */
@Config(qualifiers = "w360dp-h780dp-xxhdpi")
class FirstLaunchScreenshotTest : ScreenshotTest() {
    @Test
    fun firstLaunch_welcomesAParticipant() = screen("first-launch-360", variants = Variant.MAIN) {
        FirstLaunchScreen("", AccountCheck.Idle, onSave = { _, _, _ -> })
    }

    @Test
    fun firstLaunch_offersStayReachableAndAutoplay() = screen("first-launch-offer-360", variants = Variant.MAIN) {
        ReachableOfferScreen("alice") { _, _ -> }
    }

    /**
     * The launcher icon as launchers draw it: the adaptive icon under a circle and a squircle-like rounded mask
     * (AdaptiveIconDrawable's own default mask), and its monochrome layer tinted as Android 13+ themed icons are.
     */
    @Test
    fun launcherIcon_adaptiveAndThemed() = screen("launcher-icon", accessibility = false) {
        val context = androidx.compose.ui.platform.LocalContext.current
        val size = 432 // 144 dp at xxhdpi
        val icon = remember { context.getDrawable(org.hapticon.app.R.mipmap.ic_launcher) as android.graphics.drawable.AdaptiveIconDrawable }
        val full = remember { icon.toBitmap(size, size).asImageBitmap() }
        val themed = remember {
            val bitmap = android.graphics.Bitmap.createBitmap(size, size, android.graphics.Bitmap.Config.ARGB_8888)
            val canvas = android.graphics.Canvas(bitmap)
            val paint = android.graphics.Paint(android.graphics.Paint.ANTI_ALIAS_FLAG).apply { color = android.graphics.Color.rgb(0xE8, 0xDE, 0xF8) }
            canvas.drawCircle(size / 2f, size / 2f, size / 2f, paint)
            val mono = icon.monochrome!!.mutate()
            // The monochrome layer spans the 108 dp canvas, of which the icon shows the middle 72 dp.
            val extra = size / 4
            mono.setBounds(-extra, -extra, size + extra, size + extra)
            mono.setTint(android.graphics.Color.rgb(0x4A, 0x3A, 0xB2))
            mono.draw(canvas)
            bitmap.asImageBitmap()
        }
        androidx.compose.foundation.layout.Row(
            androidx.compose.ui.Modifier.padding(24.dp),
            horizontalArrangement = androidx.compose.foundation.layout.Arrangement.spacedBy(24.dp),
        ) {
            androidx.compose.foundation.Image(full, contentDescription = null)
            androidx.compose.foundation.Image(themed, contentDescription = null)
        }
    }

    @Test
    fun chatList_stayReachableOff_saysSoAboveTheChats() = screen("chats-empty-not-reachable-360", variants = Variant.MAIN) {
        ChatListScreen(
            ChatListUiState.Success("alice", emptyList(), reachableNote = ReachableNote.OFF), ChatListActions(),
            ChatClock(ZoneOffset.UTC, Locale.UK), 1_767_225_600_000L,
        )
    }
}
