package org.hapticon.app.feature.chat

import android.view.View
import androidx.core.graphics.Insets
import androidx.core.view.ViewCompat
import androidx.core.view.WindowInsetsCompat

/**
 * Opens an on-screen keyboard [heightDp] high as far as the app can tell: dispatches its insets (the IME type,
 * visible) to [view] and its children, as Android does when the keyboard comes up. Robolectric draws no keyboard
 * window, so this is what the app sees of one. Call it on the main thread; returns the keyboard's height in pixels.
 */
fun openKeyboard(view: View, heightDp: Int = 300): Int {
    val px = (heightDp * view.resources.displayMetrics.density).toInt()
    val insets = WindowInsetsCompat.Builder()
        .setInsets(WindowInsetsCompat.Type.ime(), Insets.of(0, 0, 0, px))
        .setVisible(WindowInsetsCompat.Type.ime(), true)
        .build()
    ViewCompat.dispatchApplyWindowInsets(view, insets)
    return px
}
