package org.hapticon.app.sync

/**
 * [text] shared from another app's share sheet, for [peer]'s conversation when the user picked it there (a sharing
 * shortcut, `Intent.EXTRA_SHORTCUT_ID`), else for the chat the user opens next.
 */
data class SharedText(val peer: String?, val text: String)
