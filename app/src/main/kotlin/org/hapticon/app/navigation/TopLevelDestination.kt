package org.hapticon.app.navigation

import androidx.compose.ui.graphics.vector.ImageVector
import org.hapticon.app.designsystem.HapticonIcons

/** The destinations of the bottom navigation bar, in bar order; each has a branch in [HapticonApp]. */
enum class TopLevelDestination(val label: String, val icon: ImageVector) {
    CHATS("Chats", HapticonIcons.Chat),
    ICONS("Icons", HapticonIcons.Vibration),
    SENSORS("Sensors", HapticonIcons.Usb),
    STUDY("Study", HapticonIcons.Study),
    GESTURES("Gestures", HapticonIcons.Gesture),
}
