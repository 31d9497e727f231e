package org.hapticon.app.feature.chat

import androidx.compose.ui.graphics.Color
import androidx.compose.foundation.background
import androidx.compose.foundation.layout.Box
import androidx.compose.foundation.layout.size
import androidx.compose.foundation.shape.CircleShape
import androidx.compose.material3.MaterialTheme
import androidx.compose.material3.Text
import androidx.compose.runtime.Composable
import androidx.compose.ui.Alignment
import androidx.compose.ui.Modifier
import androidx.compose.ui.semantics.clearAndSetSemantics
import androidx.compose.ui.unit.dp

/** Up to two initials of a user name: "alice" → "A", "bob.smith" → "BS", "x_y-z" → "XY". */
fun initialsOf(name: String): String {
    val parts = name.split('.', '_', '-', ' ').filter { it.isNotEmpty() }
    return when {
        parts.isEmpty() -> "?"
        parts.size == 1 -> parts[0].take(1).uppercase()
        else -> (parts[0].take(1) + parts[1].take(1)).uppercase()
    }
}

/**
 * The avatar colour of [name]: a hue from the name's hash at fixed saturation and lightness, so the same
 * person always gets the same colour and white initials stay readable on every hue (lightness 0.32
 * keeps the contrast with white at 4.5:1 or more, WCAG 2.x's AA level for text, even for yellow, the
 * brightest hue at equal HSL lightness).
 */
fun avatarColorOf(name: String): Color {
    val hue = Math.floorMod(name.hashCode(), 360).toFloat()
    return Color.hsl(hue, saturation = 0.45f, lightness = 0.32f)
}

/** Initials on the colour derived from the name. */
@Composable
fun Avatar(name: String, modifier: Modifier = Modifier.size(48.dp)) {
    Box(modifier.background(avatarColorOf(name), CircleShape), contentAlignment = Alignment.Center) {
        // Decoration: the name is said next to it, so TalkBack skips the initials (a lone "B" stop before "bob").
        Text(initialsOf(name), color = Color.White, style = MaterialTheme.typography.titleMedium, modifier = Modifier.clearAndSetSemantics {})
    }
}
