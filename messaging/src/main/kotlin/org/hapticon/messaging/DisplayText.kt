package org.hapticon.messaging

/**
 * Makes text a peer wrote safe to show outside the chat (a notification, the lock screen): the peer chooses every
 * character, and a control or bidirectional-formatting character could rearrange or hide what is shown around it
 * ("Trojan Source", CVE-2021-42574: U+202E turns the rest of a line around).
 */
public object DisplayText {
    /**
     * [text] with C0 and C1 control characters removed (a tab becomes a space, a line or paragraph separator a line
     * break; line breaks stay), and the bidirectional embeddings, overrides, isolates and marks removed
     * (U+200E–U+200F, U+202A–U+202E, U+2066–U+2069, U+061C).
     */
    public fun neutralise(text: String): String = buildString(text.length) {
        for (c in text) {
            when {
                c == '\n' -> append('\n')
                c == '\t' -> append(' ')
                c == '\u2028' || c == '\u2029' -> append('\n')
                Character.isISOControl(c) -> Unit
                c in BIDI_CONTROLS -> Unit
                else -> append(c)
            }
        }
    }

    private val BIDI_CONTROLS: Set<Char> = buildSet {
        add('\u061C')
        add('\u200E')
        add('\u200F')
        for (c in '\u202A'..'\u202E') add(c)
        for (c in '\u2066'..'\u2069') add(c)
    }
}
