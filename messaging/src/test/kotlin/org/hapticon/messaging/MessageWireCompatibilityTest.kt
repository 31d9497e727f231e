package org.hapticon.messaging

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.pattern.Transient
import org.hapticon.core.render.RendererKind
import org.junit.Assert.assertEquals
import org.junit.Test

/**
 * Payloads recorded from the hand-written JSON writer before the wire format moved to kotlinx-serialization
 * (written by that build, copied here byte for byte). Messages from older app versions — v1 with an icon or
 * text only, v2 with a pattern — must still decode to these exact values, and this build must write the same
 * bytes, so that the previous version reads what we send.
 */
class MessageWireCompatibilityTest {
    private val v1Icon = """{"schema":"hapticon.message","version":1,"id":"9f2c1e4a-6b7d-4c3e-8a1f-2d5e6f708192","sender":"alice",""" +
        """"sentAt":1767225600000,"text":"The quick brown fox jumps over the lazy dog","sticker":null,"icon":{"schema":"hapticon.icon",""" +
        """"version":1,"name":"knock","attack":0.005,"sustain":0.01,"level":0.5,"release":0.005,"note":57,"period":0.27,"count":3}}"""

    // The old writer escaped U+2028 (it ends a line in JavaScript) and control characters as \uXXXX.
    private val v1Escapes = "{\"schema\":\"hapticon.message\",\"version\":1,\"id\":\"0b6f3c2a-1d4e-4f5a-9b8c-7d6e5f4a3b2c\",\"sender\":\"d-1\"," +
        "\"sentAt\":1,\"text\":\"\\\"quotes\\\" \\\\ \\n line\\u2028 \u00e9 \uD83D\uDE00 \\u0001\",\"sticker\":\"wave\",\"icon\":{\"schema\":\"hapticon.icon\"," +
        "\"version\":1,\"name\":\"stroke\",\"attack\":1,\"sustain\":1,\"level\":0.3,\"release\":1,\"note\":65,\"period\":2.6,\"count\":4}}"

    private val v2Pattern = """{"schema":"hapticon.message","version":2,"id":"$ID_1","sender":"alice","sentAt":5,"text":"boing",""" +
        """"sticker":null,"icon":null,"pattern":{"schema":"hapticon.pattern","version":1,"name":"boing",""" +
        """"amplitude":[{"time":0,"amplitude":0},{"time":0.05,"amplitude":1},{"time":0.4,"amplitude":0}],""" +
        """"frequency":[{"time":0,"hertz":220},{"time":0.4,"hertz":110}],""" +
        """"transients":[{"time":0.1,"intensity":0.8,"sharpness":0.4}]}}"""

    private val receipt = """{"schema":"hapticon.receipt","version":1,"messageId":"$ID_1","from":"bob","state":"read","at":1767225600001}"""
    private val hand = """{"schema":"hapticon.hand","version":1,"from":"bob","thumb":12.5,"middle":48,"at":42}"""
    private val capabilities = """{"schema":"hapticon.capabilities","version":1,"user":"bob","renderer":"amplitude-waveform",""" +
        """"amplitudeControl":true,"apiLevel":34,"resonantFrequencyHz":170}"""
    private val bareCapabilities = """{"schema":"hapticon.capabilities","version":1,"user":"carol","renderer":"envelope",""" +
        """"amplitudeControl":false,"apiLevel":null,"resonantFrequencyHz":null}"""

    // Written by the build before envelope limits were published (85d0595, before the pitch members): an API 36 phone.
    private val pitchCapabilities = """{"schema":"hapticon.capabilities","version":1,"user":"bob","renderer":"envelope","amplitudeControl":true,""" +
        """"apiLevel":36,"resonantFrequencyHz":170,"envelopeEffects":true,"frequencyMinHz":120,"frequencyMaxHz":240,"pitchFit":"clamp"}"""

    @Test
    fun decode_recordedV1IconMessage_givesTheExactMessageAndIsWrittenIdentically() {
        val expected = ChatMessage(
            "9f2c1e4a-6b7d-4c3e-8a1f-2d5e6f708192", "alice", 1_767_225_600_000L, "The quick brown fox jumps over the lazy dog",
            icon = HapticIcon("knock", 0.005, 0.01, 0.5, 0.005, 57.0, 0.27, 3),
        )
        assertEquals(Decoded.Accepted(expected), MessageCodec.decodeInbox(v1Icon.toByteArray()))
        assertEquals(v1Icon, String(MessageCodec.encode(expected), Charsets.UTF_8))
    }

    @Test
    fun decode_recordedV1MessageWithEscapes_givesTheExactText() {
        val decoded = MessageCodec.decodeInbox(v1Escapes.toByteArray()) as Decoded.Accepted
        val expected = ChatMessage(
            "0b6f3c2a-1d4e-4f5a-9b8c-7d6e5f4a3b2c", "d-1", 1, "\"quotes\" \\ \n line\u2028 \u00e9 \uD83D\uDE00 \u0001",
            sticker = "wave", icon = HapticIcon("stroke", 1.0, 1.0, 0.3, 1.0, 65.0, 2.6, 4),
        )
        assertEquals(expected, decoded.value)
        // What we write now differs only in U+2028, which kotlinx leaves unescaped (valid JSON, read the same).
        assertEquals(v1Escapes.replace("\\u2028", "\u2028"), String(MessageCodec.encode(expected), Charsets.UTF_8))
    }

    @Test
    fun decode_recordedV2PatternMessage_givesTheExactPatternAndIsWrittenIdentically() {
        val decoded = (MessageCodec.decodeInbox(v2Pattern.toByteArray()) as Decoded.Accepted).value as ChatMessage
        val pattern = decoded.pattern!!
        assertEquals("boing", pattern.name)
        assertEquals(listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.05, 1.0), AmplitudeKey(0.4, 0.0)), pattern.amplitude)
        assertEquals(listOf(FrequencyKey(0.0, 220.0), FrequencyKey(0.4, 110.0)), pattern.frequency)
        assertEquals(listOf(Transient(0.1, 0.8, 0.4)), pattern.transients)
        assertEquals(ChatMessage(ID_1, "alice", 5, "boing", pattern = HapticPattern("boing", pattern.amplitude, pattern.frequency, pattern.transients)), decoded)
        assertEquals(v2Pattern, String(MessageCodec.encode(decoded), Charsets.UTF_8))
    }

    @Test
    fun decode_recordedReceiptAndHandPose_giveTheExactValuesAndAreWrittenIdentically() {
        val r = Receipt(ID_1, "bob", ReceiptState.READ, 1_767_225_600_001L)
        assertEquals(Decoded.Accepted(r), MessageCodec.decodeInbox(receipt.toByteArray()))
        assertEquals(receipt, String(MessageCodec.encode(r), Charsets.UTF_8))
        val pose = HandPose("bob", 12.5, 48.0, 42)
        assertEquals(Decoded.Accepted(pose), MessageCodec.decodeInbox(hand.toByteArray()))
        assertEquals(hand, String(MessageCodec.encode(pose), Charsets.UTF_8))
    }

    @Test
    fun decode_recordedCapabilities_giveTheExactValuesAndAreWrittenIdentically() {
        val full = Capabilities("bob", RendererKind.AMPLITUDE_WAVEFORM, true, 34, 170.0)
        assertEquals(Decoded.Accepted(full), MessageCodec.decodeCapabilities(capabilities.toByteArray()))
        assertEquals(capabilities, String(MessageCodec.encode(full), Charsets.UTF_8))
        val bare = Capabilities("carol", RendererKind.ENVELOPE, false, null, null)
        assertEquals(Decoded.Accepted(bare), MessageCodec.decodeCapabilities(bareCapabilities.toByteArray()))
        assertEquals(bareCapabilities, String(MessageCodec.encode(bare), Charsets.UTF_8))
    }

    @Test
    fun decode_recordedCapabilitiesWithoutEnvelopeLimits_decodeWithNoneAndAreWrittenIdentically() {
        val bob = Capabilities(
            "bob", RendererKind.ENVELOPE, true, 36, 170.0, envelopeEffects = true, frequencyRangeHz = 120.0..240.0, pitchFit = PitchFit.CLAMP,
        )
        val decoded = MessageCodec.decodeCapabilities(pitchCapabilities.toByteArray())
        assertEquals(Decoded.Accepted(bob), decoded)
        // No limits published: the sender falls back to the guaranteed ones (PeerPitch), it does not reject the peer.
        assertEquals(null, (decoded as Decoded.Accepted).value.envelopeLimits)
        assertEquals(pitchCapabilities, String(MessageCodec.encode(bob), Charsets.UTF_8))
        // The new members only follow the old ones, so an older reader (which ignores unknown members) sees its document.
        val withLimits = String(MessageCodec.encode(bob.copy(envelopeLimits = EnvelopeEffectInfo(16, 20, 1000, 16_000))), Charsets.UTF_8)
        assertEquals(
            pitchCapabilities.removeSuffix("}") +
                ""","envelopeMaxControlPoints":16,"envelopeMinControlPointMillis":20,"envelopeMaxControlPointMillis":1000,"envelopeMaxDurationMillis":16000}""",
            withLimits,
        )
    }

    @Test
    fun decode_duplicateMemberOrWholeNumberWithFraction_keepsTheStrictReadersRules() {
        val duplicate = MessageCodec.decodeInbox(receipt.replace("\"from\":\"bob\"", "\"from\":\"bob\",\"from\":\"eve\"").toByteArray()) as Decoded.Rejected
        assertEquals(RejectionReason.MALFORMED_JSON, duplicate.reason)
        assertEquals("duplicate member name \"from\" at offset 105", duplicate.detail)
        // JavaScript writes 5 as 5.0 sometimes; a whole number with a fraction was always accepted for an integer member.
        val js = MessageCodec.decodeInbox(receipt.replace("1767225600001", "1767225600001.0").toByteArray()) as Decoded.Accepted
        assertEquals(1_767_225_600_001L, (js.value as Receipt).atMillis)
    }
}
