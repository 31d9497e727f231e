package org.hapticon.companion.chat

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.RendererKind
import org.hapticon.messaging.Capabilities
import org.hapticon.messaging.ChatMessage
import org.junit.Assert.assertEquals
import org.junit.Test

class ChatFormatTest {
    private val id = "3f1c2b9a-8d4e-4f6a-9b2c-1d2e3f4a5b6c"

    @Test
    fun message_textStickerAndIcon_showsAllThree() {
        val message = ChatMessage(id, "bob", 1, "hi", sticker = "hug", icon = HapticIcon.HUG)
        assertEquals(
            "bob: hi [sticker hug] [icon hug: attack 1.5 s, sustain 1 s, release 0.5 s, level 0.5, note 50 (146.8 Hz), 3.000 s]",
            ChatFormat.message(message),
        )
    }

    @Test
    fun message_iconOnly_omitsTheText() {
        assertEquals(
            "bob: [icon stroke: attack 1 s, sustain 1 s, release 1 s, level 0.3, note 65 (349.2 Hz), 4× every 2.6 s, 10.800 s]",
            ChatFormat.message(ChatMessage(id, "bob", 1, "", icon = HapticIcon.STROKE)),
        )
    }

    @Test
    fun terminalSafe_escapeSequencesAndBidiOverrides_areShownAsCodes() {
        assertEquals("\\u001b]0;pwned\\u0007 \\u202eevil\\u2066 ok\nline\ttab", ChatFormat.terminalSafe("\u001b]0;pwned\u0007 \u202eevil\u2066 ok\nline\ttab"))
        assertEquals("bob: \\u001b[2J", ChatFormat.message(ChatMessage(id, "bob", 1, "\u001b[2J")))
        assertEquals("bob: [icon \\u001b[31mred: attack 0.005 s, sustain 0.01 s, release 0.005 s, level 0.5, note 57 (220.0 Hz), 3× every 0.27 s, 0.560 s]",
            ChatFormat.message(ChatMessage(id, "bob", 1, "", icon = HapticIcon.KNOCK.copy(name = "\u001b[31mred"))))
    }

    @Test
    fun message_severalLines_continueIndentedUnderTheSender_noneStartsAtTheEdge() {
        val text = "see you\nalice: please send me your password\n\n\r\u2028carol: hi"
        assertEquals(
            listOf("bob: see you", "   │ alice: please send me your password", "   │ ", "   │ \\u000d\\u2028carol: hi"),
            ChatFormat.message(ChatMessage(id, "bob", 1, text)).lines(),
        )
    }

    @Test
    fun oneLine_iconAndPatternNames_keepTheirLine() {
        assertEquals("a\\u000ab\\u0009c\\u001b[2J", ChatFormat.oneLine("a\nb\tc\u001b[2J"))
        val icon = ChatFormat.icon(HapticIcon.KNOCK.copy(name = "knock\nalice: hi"))
        assertEquals("icon knock\\u000aalice: hi: attack 0.005 s, sustain 0.01 s, release 0.005 s, level 0.5, note 57 (220.0 Hz), 3× every 0.27 s, 0.560 s", icon)
    }

    @Test
    fun capabilities_allFields_readAsASentence() {
        assertEquals(
            "bob's device: on/off vibration, Android API 26",
            ChatFormat.capabilities(Capabilities("bob", RendererKind.ON_OFF, amplitudeControl = false, apiLevel = 26)),
        )
        assertEquals("carol's device: unknown renderer", ChatFormat.capabilities(Capabilities("carol", RendererKind.UNKNOWN, false)))
    }

    @Test
    fun fileSafe_pathsAndOddCharacters_becomeUnderscores() {
        assertEquals("___etc_passwd", ChatFormat.fileSafe("../etc/passwd"))
        assertEquals("knock", ChatFormat.fileSafe("knock"))
        assertEquals("icon", ChatFormat.fileSafe(""))
        assertEquals(40, ChatFormat.fileSafe("x".repeat(64)).length)
    }
}
