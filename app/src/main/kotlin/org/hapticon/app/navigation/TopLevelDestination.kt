package org.hapticon.app.navigation

import androidx.compose.ui.graphics.vector.ImageVector
import org.hapticon.app.designsystem.HapticonIcons

/**
 * The destinations of the bottom navigation bar, in bar order. Adding one (the next task adds
 * `CHATS("Chats", HapticonIcons.Chat)`) takes an entry here and a branch in [HapticonApp].
 */
enum class TopLevelDestination(val label: String, val icon: ImageVector) {
    CHATS("Chats", HapticonIcons.Chat),
    ICONS("Icons", HapticonIcons.Vibration),
    SENSORS("Sensors", HapticonIcons.Usb),
    GESTURES("Gestures", HapticonIcons.Gesture),
}
