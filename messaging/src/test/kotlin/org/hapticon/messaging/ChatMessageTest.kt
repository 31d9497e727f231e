package org.hapticon.messaging

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.render.RendererKind
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

class ChatMessageTest {
    @Test
    fun compose_usesTheClockAndAFreshLowerCaseUuid() {
        val clock = FakeClock(NEW_YEAR_2026)
        val first = ChatMessage.compose("alice", "hi", icon = HapticIcon.HUG, clock = clock)
        val second = ChatMessage.compose("alice", "hi", icon = HapticIcon.HUG, clock = clock)
        assertEquals(NEW_YEAR_2026, first.sentAtMillis)
        assertTrue(first.id, UUID_FORM.matches(first.id))
        assertTrue(first.id != second.id)
        assertEquals(first.copy(id = second.id), second)
    }

    @Test
    fun constructor_eachBrokenRule_throwsNamingReasonAndField() {
        val cases: List<Triple<RejectionReason, String, () -> ChatMessage>> = listOf(
            Triple(RejectionReason.INVALID_VALUE, "id", { ChatMessage(ID_1.uppercase(), "a", 1, "x") }),
            Triple(RejectionReason.INVALID_VALUE, "sender", { ChatMessage(ID_1, "a#", 1, "x") }),
            Triple(RejectionReason.INVALID_VALUE, "sender", { ChatMessage(ID_1, "a".repeat(Topics.MAX_USER_NAME_LENGTH + 1), 1, "x") }),
            Triple(RejectionReason.INVALID_VALUE, "sentAt", { ChatMessage(ID_1, "a", -1, "x") }),
            Triple(RejectionReason.TEXT_TOO_LONG, "text", { ChatMessage(ID_1, "a", 1, "x".repeat(MessageLimits.MAX_TEXT_LENGTH + 1)) }),
            Triple(RejectionReason.INVALID_VALUE, "text", { ChatMessage(ID_1, "a", 1, "x\uD800y") }),
            Triple(RejectionReason.INVALID_VALUE, "text", { ChatMessage(ID_1, "a", 1, "") }),
            Triple(RejectionReason.INVALID_VALUE, "sticker", { ChatMessage(ID_1, "a", 1, "x", sticker = "") }),
            Triple(RejectionReason.INVALID_VALUE, "icon.name", { ChatMessage(ID_1, "a", 1, "x", icon = HapticIcon.KNOCK.copy(name = "\uDC00")) }),
            Triple(RejectionReason.ICON_TOO_LONG, "icon", { ChatMessage(ID_1, "a", 1, "x", icon = HapticIcon.LONGEST_ALLOWED) }),
        )
        for ((reason, field, build) in cases) {
            val e = assertThrows(InvalidMessageException::class.java) { build() }
            assertEquals(e.message, reason to field, e.reason to e.field)
        }
    }

    @Test
    fun constructor_stickerOrIconWithoutText_isAMessage() {
        assertEquals("", ChatMessage(ID_1, "a", 1, "", sticker = "hug").text)
        assertEquals(HapticIcon.STROKE, ChatMessage(ID_1, "a", 1, "", icon = HapticIcon.STROKE).icon)
    }

    @Test
    fun receiptAndCapabilities_brokenRules_throwNamingTheField() {
        val cases: List<Pair<String, () -> Any>> = listOf(
            "messageId" to { Receipt("x", "bob", ReceiptState.READ, 1) },
            "from" to { Receipt(ID_1, "", ReceiptState.READ, 1) },
            "at" to { Receipt(ID_1, "bob", ReceiptState.READ, MessageLimits.MAX_TIMESTAMP_MILLIS + 1) },
            "user" to { Capabilities("bob/x", RendererKind.NONE, false) },
            "apiLevel" to { Capabilities("bob", RendererKind.NONE, false, apiLevel = 0) },
            "resonantFrequencyHz" to { Capabilities("bob", RendererKind.NONE, false, resonantFrequencyHz = Double.NaN) },
            "envelopeMaxControlPoints" to { Capabilities("bob", RendererKind.ENVELOPE, true, envelopeLimits = EnvelopeEffectInfo(0, 20, 1000, 16_000)) },
            "envelopeMinControlPointMillis" to { Capabilities("bob", RendererKind.ENVELOPE, true, envelopeLimits = EnvelopeEffectInfo(16, 2000, 1000, 16_000)) },
            "envelopeMaxDurationMillis" to { Capabilities("bob", RendererKind.ENVELOPE, true, envelopeLimits = EnvelopeEffectInfo(16, 20, 1000, 999)) },
        )
        for ((field, build) in cases) {
            val e = assertThrows(InvalidMessageException::class.java) { build() }
            assertEquals(e.message, RejectionReason.INVALID_VALUE to field, e.reason to e.field)
        }
    }
}
