package org.hapticon.messaging

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.EnvelopeEffectInfo
import org.hapticon.core.pattern.PitchFit
import org.hapticon.core.render.RendererKind
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Test

class MessageCodecTest {
    private val message = ChatMessage(ID_1, "alice", NEW_YEAR_2026, "hello", sticker = "hug", icon = HapticIcon.KNOCK)

    @Test
    fun encode_messageWithStickerAndIcon_writesTheVersionOneWireFormat() {
        val expected = """{"schema":"hapticon.message","version":1,"id":"$ID_1","sender":"alice","sentAt":1767225600000,""" +
            """"text":"hello","sticker":"hug","icon":{"schema":"hapticon.icon","version":1,"name":"knock","attack":0.005,""" +
            """"sustain":0.01,"level":0.5,"release":0.005,"note":57,"period":0.27,"count":3}}"""
        assertEquals(expected, String(MessageCodec.encode(message), Charsets.UTF_8))
    }

    @Test
    fun encode_textOnlyMessage_writesNullStickerAndIcon() {
        val plain = ChatMessage(ID_1, "bob", 5, "hi")
        assertEquals(
            """{"schema":"hapticon.message","version":1,"id":"$ID_1","sender":"bob","sentAt":5,"text":"hi","sticker":null,"icon":null}""",
            String(MessageCodec.encode(plain), Charsets.UTF_8),
        )
    }

    @Test
    fun decodeInbox_encodedMessages_roundTripExactly() {
        val messages = listOf(
            message,
            ChatMessage(ID_2, "bob", 0, "only text"),
            ChatMessage(ID_2, "carol.b", MessageLimits.MAX_TIMESTAMP_MILLIS, "", sticker = "wave"),
            ChatMessage(ID_2, "d-1", 1, "\"quotes\" \\ \n line\u2028 😀 \u0001", icon = HapticIcon.STROKE),
        )
        for (original in messages) {
            assertEquals(Decoded.Accepted(original), MessageCodec.decodeInbox(MessageCodec.encode(original)))
        }
    }

    @Test
    fun decodeInbox_encodedReceipts_roundTripExactly() {
        for (state in ReceiptState.entries) {
            val receipt = Receipt(ID_1, "bob", state, NEW_YEAR_2026 + 1)
            assertEquals(Decoded.Accepted(receipt), MessageCodec.decodeInbox(MessageCodec.encode(receipt)))
        }
    }

    @Test
    fun handPose_encodesTheVersionOneWireFormatAndRoundTrips() {
        val pose = HandPose("bob", 12.5, 48.25, 42)
        assertEquals(
            """{"schema":"hapticon.hand","version":1,"from":"bob","thumb":12.5,"middle":48.25,"at":42}""",
            String(MessageCodec.encode(pose), Charsets.UTF_8),
        )
        assertEquals(Decoded.Accepted(pose), MessageCodec.decodeInbox(MessageCodec.encode(pose)))
    }

    @Test
    fun handPose_anglesOutOfRangeOrMissing_areRejectedNamingTheField() {
        assertRejected(RejectionReason.INVALID_VALUE, "thumb", """{"schema":"hapticon.hand","version":1,"from":"bob","thumb":1e9,"middle":0,"at":1}""")
        assertRejected(RejectionReason.INVALID_VALUE, "middle", """{"schema":"hapticon.hand","version":1,"from":"bob","thumb":0,"middle":-31,"at":1}""")
        assertRejected(RejectionReason.INVALID_VALUE, "middle", """{"schema":"hapticon.hand","version":1,"from":"bob","thumb":0,"middle":1e400,"at":1}""")
        assertRejected(RejectionReason.MISSING_FIELD, "thumb", """{"schema":"hapticon.hand","version":1,"from":"bob","middle":0,"at":1}""")
        assertRejected(RejectionReason.INVALID_VALUE, "from", """{"schema":"hapticon.hand","version":1,"from":"bob/x","thumb":0,"middle":0,"at":1}""")
        assertEquals(180.0, HandPose("bob", 180.0, -30.0, 0).thumbDegrees, 0.0)
    }

    @Test
    fun encode_readReceipt_writesTheVersionOneWireFormat() {
        val receipt = Receipt(ID_1, "bob", ReceiptState.READ, 42)
        assertEquals(
            """{"schema":"hapticon.receipt","version":1,"messageId":"$ID_1","from":"bob","state":"read","at":42}""",
            String(MessageCodec.encode(receipt), Charsets.UTF_8),
        )
    }

    @Test
    fun encode_feltReceipt_writesStateFelt() {
        val receipt = Receipt(ID_1, "bob", ReceiptState.FELT, 42)
        assertEquals(
            """{"schema":"hapticon.receipt","version":1,"messageId":"$ID_1","from":"bob","state":"felt","at":42}""",
            String(MessageCodec.encode(receipt), Charsets.UTF_8),
        )
    }

    @Test
    fun decodeCapabilities_encodedCapabilities_roundTripExactly() {
        val all = listOf(
            Capabilities("bob", RendererKind.AMPLITUDE_WAVEFORM, amplitudeControl = true, apiLevel = 34, resonantFrequencyHz = 170.5),
            Capabilities("alice", RendererKind.AUDIO, amplitudeControl = false),
            Capabilities("carol", RendererKind.ON_OFF, amplitudeControl = false, apiLevel = 26),
        )
        for (original in all) {
            assertEquals(Decoded.Accepted(original), MessageCodec.decodeCapabilities(MessageCodec.encode(original)))
        }
        assertEquals(
            """{"schema":"hapticon.capabilities","version":1,"user":"bob","renderer":"amplitude-waveform","amplitudeControl":true,""" +
                """"apiLevel":34,"resonantFrequencyHz":170.5}""",
            String(MessageCodec.encode(all[0]), Charsets.UTF_8),
        )
    }

    @Test
    fun decodeCapabilities_frequencyProfileAndPitchFit_roundTripExactly() {
        val bob = Capabilities(
            "bob", RendererKind.ENVELOPE, amplitudeControl = true, apiLevel = 36, resonantFrequencyHz = 170.0,
            envelopeEffects = true, frequencyRangeHz = 120.0..240.0, pitchFit = PitchFit.CLAMP,
        )
        assertEquals(Decoded.Accepted(bob), MessageCodec.decodeCapabilities(MessageCodec.encode(bob)))
        assertEquals(
            """{"schema":"hapticon.capabilities","version":1,"user":"bob","renderer":"envelope","amplitudeControl":true,""" +
                """"apiLevel":36,"resonantFrequencyHz":170,"envelopeEffects":true,"frequencyMinHz":120,"frequencyMaxHz":240,"pitchFit":"clamp"}""",
            String(MessageCodec.encode(bob), Charsets.UTF_8),
        )
        // An older build's document has none of them; a newer build's fit this one does not know reads as unknown.
        val newer = """{"schema":"hapticon.capabilities","version":1,"user":"bob","renderer":"envelope","amplitudeControl":true,"pitchFit":"stretch"}"""
        assertEquals(Decoded.Accepted(Capabilities("bob", RendererKind.ENVELOPE, true)), MessageCodec.decodeCapabilities(newer.toByteArray()))
    }

    @Test
    fun decodeCapabilities_badFrequencyRange_rejectedByField() {
        fun caps(members: String) = """{"schema":"hapticon.capabilities","version":1,"user":"bob","renderer":"envelope","amplitudeControl":true,$members}"""
        assertCapabilitiesRejected(RejectionReason.MISSING_FIELD, "frequencyMaxHz", caps(""""frequencyMinHz":120"""))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "frequencyMinHz", caps(""""frequencyMinHz":240,"frequencyMaxHz":120"""))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "frequencyMinHz", caps(""""frequencyMinHz":0,"frequencyMaxHz":120"""))
        assertCapabilitiesRejected(RejectionReason.WRONG_TYPE, "envelopeEffects", caps(""""envelopeEffects":"yes""""))
    }

    @Test
    fun decodeCapabilities_envelopeLimits_roundTripExactlyAfterThePitchMembers() {
        val bob = Capabilities(
            "bob", RendererKind.ENVELOPE, amplitudeControl = true, apiLevel = 36, envelopeEffects = true,
            frequencyRangeHz = 120.0..240.0, pitchFit = PitchFit.OCTAVES, envelopeLimits = EnvelopeEffectInfo(4, 50, 500, 2000),
        )
        assertEquals(
            """{"schema":"hapticon.capabilities","version":1,"user":"bob","renderer":"envelope","amplitudeControl":true,""" +
                """"apiLevel":36,"resonantFrequencyHz":null,"envelopeEffects":true,"frequencyMinHz":120,"frequencyMaxHz":240,"pitchFit":"octaves",""" +
                """"envelopeMaxControlPoints":4,"envelopeMinControlPointMillis":50,"envelopeMaxControlPointMillis":500,"envelopeMaxDurationMillis":2000}""",
            String(MessageCodec.encode(bob), Charsets.UTF_8),
        )
        assertEquals(Decoded.Accepted(bob), MessageCodec.decodeCapabilities(MessageCodec.encode(bob)))
    }

    @Test
    fun decodeCapabilities_badEnvelopeLimits_rejectedByField() {
        fun caps(points: String, min: String, max: String, total: String) =
            """{"schema":"hapticon.capabilities","version":1,"user":"bob","renderer":"envelope","amplitudeControl":true,""" +
                listOf("envelopeMaxControlPoints" to points, "envelopeMinControlPointMillis" to min, "envelopeMaxControlPointMillis" to max, "envelopeMaxDurationMillis" to total)
                    .filter { it.second.isNotEmpty() }.joinToString(",") { "\"${it.first}\":${it.second}" } + "}"
        // All four or none: one VibratorEnvelopeEffectInfo.
        assertCapabilitiesRejected(RejectionReason.MISSING_FIELD, "envelopeMaxDurationMillis", caps("4", "50", "500", ""))
        assertCapabilitiesRejected(RejectionReason.MISSING_FIELD, "envelopeMaxControlPoints", caps("", "50", "500", "2000"))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "envelopeMaxControlPoints", caps("0", "50", "500", "2000"))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "envelopeMaxControlPoints", caps("1001", "50", "500", "2000"))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "envelopeMaxControlPoints", caps("4.5", "50", "500", "2000"))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "envelopeMinControlPointMillis", caps("4", "0", "500", "2000"))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "envelopeMinControlPointMillis", caps("4", "600", "500", "2000"))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "envelopeMaxDurationMillis", caps("4", "50", "500", "400"))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "envelopeMaxDurationMillis", caps("4", "50", "500", "600001"))
        assertCapabilitiesRejected(RejectionReason.WRONG_TYPE, "envelopeMinControlPointMillis", caps("4", "\"50\"", "500", "2000"))
        // The largest accepted limits still decode.
        val largest = MessageCodec.decodeCapabilities(caps("1000", "1", "600000", "600000").toByteArray()) as Decoded.Accepted
        assertEquals(EnvelopeEffectInfo(1000, 1, 600_000, 600_000), largest.value.envelopeLimits)
    }

    @Test
    fun decodeCapabilities_rendererFromANewerClient_decodesAsUnknown() {
        val json = """{"schema":"hapticon.capabilities","version":1,"user":"bob","renderer":"piezo-array","amplitudeControl":true}"""
        assertEquals(
            Decoded.Accepted(Capabilities("bob", RendererKind.UNKNOWN, amplitudeControl = true)),
            MessageCodec.decodeCapabilities(json.toByteArray()),
        )
    }

    @Test
    fun decodeInbox_upperCaseIdAndUnknownMembers_normalisesTheIdAndIgnoresTheRest() {
        val json = """{"schema":"hapticon.message","version":1,"id":"${ID_1.uppercase()}","sender":"alice","sentAt":1.7e12,""" +
            """"text":"hi","future":{"nested":[1,2]},"sticker":null}"""
        assertEquals(Decoded.Accepted(ChatMessage(ID_1, "alice", 1_700_000_000_000, "hi")), MessageCodec.decodeInbox(json.toByteArray()))
    }

    @Test
    fun decodeInbox_payloadOverTheLimit_isRejectedBeforeParsing() {
        // Not JSON at all: only a size check that comes first can reject it as too large.
        val payload = ByteArray(MessageLimits.MAX_PAYLOAD_BYTES + 1) { '{'.code.toByte() }
        assertRejected(RejectionReason.PAYLOAD_TOO_LARGE, null, payload)
    }

    @Test
    fun decodeInbox_oneMegabyteText_isRejectedAsTooLarge() {
        val json = """{"schema":"hapticon.message","version":1,"id":"$ID_1","sender":"a","sentAt":1,"text":"${"x".repeat(1 shl 20)}"}"""
        assertRejected(RejectionReason.PAYLOAD_TOO_LARGE, null, json)
    }

    @Test
    fun decodeInbox_payloadAtTheLimit_isParsed() {
        val prefix = """{"schema":"hapticon.message","version":1,"id":"$ID_1","sender":"a","sentAt":1,"text":"x","pad":""""
        val json = prefix + " ".repeat(MessageLimits.MAX_PAYLOAD_BYTES - prefix.length - 2) + "\"}"
        assertEquals(MessageLimits.MAX_PAYLOAD_BYTES, json.length)
        assertEquals(Decoded.Accepted(ChatMessage(ID_1, "a", 1, "x")), MessageCodec.decodeInbox(json.toByteArray()))
    }

    @Test
    fun decodeInbox_malformedInput_isRejectedAsMalformedJson() {
        val inputs = listOf(
            "{\"schema\":".toByteArray(),
            "".toByteArray(),
            """{"schema":"hapticon.message","version":NaN}""".toByteArray(),
            """{"a":1,"a":2}""".toByteArray(),
            byteArrayOf('"'.code.toByte(), 0xC3.toByte(), 0x28, '"'.code.toByte()), // invalid UTF-8
            ("""{"a":""" + "[".repeat(MessageLimits.MAX_JSON_DEPTH) + "]".repeat(MessageLimits.MAX_JSON_DEPTH) + "}").toByteArray(),
        )
        for (input in inputs) assertRejected(RejectionReason.MALFORMED_JSON, null, input)
    }

    @Test
    fun decodeInbox_jsonThatIsNotAnObject_isRejected() {
        for (json in listOf("[1]", "\"text\"", "42", "null", "true")) assertRejected(RejectionReason.NOT_AN_OBJECT, null, json)
    }

    @Test
    fun decodeInbox_missingOrForeignSchema_isRejectedAsUnknownSchema() {
        assertRejected(RejectionReason.UNKNOWN_SCHEMA, "schema", """{"version":1}""")
        assertRejected(RejectionReason.UNKNOWN_SCHEMA, "schema", """{"schema":"hapticon.icon","version":1}""")
        assertRejected(RejectionReason.UNKNOWN_SCHEMA, "schema", """{"schema":5,"version":1}""")
        // A capabilities document does not belong in an inbox, nor a message on a capabilities topic.
        assertRejected(RejectionReason.UNKNOWN_SCHEMA, "schema", """{"schema":"hapticon.capabilities","version":1}""")
        assertEquals(
            RejectionReason.UNKNOWN_SCHEMA,
            (MessageCodec.decodeCapabilities(MessageCodec.encode(message)) as Decoded.Rejected).reason,
        )
    }

    @Test
    fun decodeInbox_versionOtherThanOneOrTwo_isRejectedAsUnsupported() {
        for (version in listOf("3", "0", "-1", "1.5", "1e300", "\"1\"", "null", "true")) {
            assertRejected(RejectionReason.UNSUPPORTED_VERSION, "version", messageJson(version = version))
        }
        assertRejected(RejectionReason.UNSUPPORTED_VERSION, "version", """{"schema":"hapticon.receipt"}""")
    }

    @Test
    fun decodeInbox_requiredMemberMissingOrNull_isRejectedAsMissingField() {
        assertRejected(RejectionReason.MISSING_FIELD, "id", messageJson(id = null))
        assertRejected(RejectionReason.MISSING_FIELD, "sender", messageJson(sender = null))
        assertRejected(RejectionReason.MISSING_FIELD, "sentAt", messageJson(sentAt = null))
        assertRejected(RejectionReason.MISSING_FIELD, "text", messageJson(text = "null"))
        assertRejected(RejectionReason.MISSING_FIELD, "state", """{"schema":"hapticon.receipt","version":1,"messageId":"$ID_1","from":"b","at":1}""")
    }

    @Test
    fun decodeInbox_memberOfTheWrongType_isRejectedAsWrongType() {
        assertRejected(RejectionReason.WRONG_TYPE, "text", messageJson(text = "5"))
        assertRejected(RejectionReason.WRONG_TYPE, "text", messageJson(text = "[\"hi\"]"))
        assertRejected(RejectionReason.WRONG_TYPE, "sentAt", messageJson(sentAt = "\"1767225600000\""))
        assertRejected(RejectionReason.WRONG_TYPE, "id", messageJson(id = "{}"))
        assertRejected(RejectionReason.WRONG_TYPE, "sticker", messageJson(extra = ""","sticker":true"""))
    }

    @Test
    fun decodeInbox_impossibleValues_areRejectedAsInvalidValue() {
        val cases = listOf(
            "sentAt" to messageJson(sentAt = "1e400"), // overflows to infinity
            "sentAt" to messageJson(sentAt = "-1e400"),
            "sentAt" to messageJson(sentAt = "1.5"),
            "sentAt" to messageJson(sentAt = "-1"),
            "sentAt" to messageJson(sentAt = "1e17"), // year 3 million
            "sentAt" to messageJson(sentAt = "123456789012345678901234567890"),
            "id" to messageJson(id = "\"not-a-uuid\""),
            "sender" to messageJson(sender = "\"a/b\""),
            "sender" to messageJson(sender = "\"+\""),
            "sender" to messageJson(sender = "\"\""),
            "sticker" to messageJson(extra = ""","sticker":"Hug!""""),
            "text" to messageJson(text = "\"   \""), // nothing to show
        )
        for ((field, json) in cases) assertRejected(RejectionReason.INVALID_VALUE, field, json)
        assertRejected(
            RejectionReason.INVALID_VALUE, "state",
            """{"schema":"hapticon.receipt","version":1,"messageId":"$ID_1","from":"bob","state":"seen","at":1}""",
        )
    }

    @Test
    fun decodeInbox_textLongerThanTheLimit_isRejectedAsTextTooLong() {
        assertRejected(RejectionReason.TEXT_TOO_LONG, "text", messageJson(text = "\"${"x".repeat(MessageLimits.MAX_TEXT_LENGTH + 1)}\""))
    }

    @Test
    fun decodeInbox_textAtTheLimitInAstralCharacters_isAccepted() {
        // 4000 emoji are 8000 UTF-16 units but 4000 characters.
        val text = "😀".repeat(MessageLimits.MAX_TEXT_LENGTH)
        val decoded = MessageCodec.decodeInbox(messageJson(text = "\"$text\"").toByteArray())
        assertEquals(text, ((decoded as Decoded.Accepted).value as ChatMessage).text)
    }

    @Test
    fun decodeInbox_invalidIcon_isRejectedNamingTheIconField() {
        val knock = """{"schema":"hapticon.icon","version":1,"name":"knock","attack":0.005,"sustain":0.01,"level":0.5,"release":0.005,"note":57"""
        assertRejected(RejectionReason.INVALID_ICON, "icon.attack", messageJson(extra = ""","icon":${knock.replace("0.005,\"sustain", "\"abc\",\"sustain")}}"""))
        assertRejected(RejectionReason.INVALID_ICON, "icon.level", messageJson(extra = ""","icon":${knock.replace("\"level\":0.5", "\"level\":1e400")}}"""))
        assertRejected(RejectionReason.INVALID_ICON, "icon.version", messageJson(extra = ""","icon":${knock.replace("\"version\":1", "\"version\":2")}}"""))
        assertRejected(RejectionReason.INVALID_ICON, "icon", messageJson(extra = ""","icon":"knock""""))
        // Ten minutes of vibration: the core's 30 s safety cap refuses it.
        assertRejected(RejectionReason.INVALID_ICON, "icon.duration", messageJson(extra = ""","icon":$knock,"period":10,"count":60}"""))
    }

    @Test
    fun decodeInbox_iconLongerThanAMessageMayPlay_isRejectedAsIconTooLong() {
        // 20 s: a valid icon, but over the 15 s a message may vibrate.
        assertRejected(RejectionReason.ICON_TOO_LONG, "icon", messageJson(extra = ""","icon":{"schema":"hapticon.icon","version":1,"name":"long","attack":5,"sustain":10,"level":0.5,"release":5,"note":57}"""))
    }

    @Test
    fun decodeCapabilities_badMembers_areRejectedByField() {
        fun caps(members: String) = """{"schema":"hapticon.capabilities","version":1,"user":"bob",$members}"""
        assertEquals(Decoded.Rejected(RejectionReason.MISSING_FIELD, "amplitudeControl", "missing"), MessageCodec.decodeCapabilities(caps(""""renderer":"none"""").toByteArray()))
        assertCapabilitiesRejected(RejectionReason.WRONG_TYPE, "amplitudeControl", caps(""""renderer":"none","amplitudeControl":"yes""""))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "apiLevel", caps(""""renderer":"none","amplitudeControl":true,"apiLevel":1e300"""))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "apiLevel", caps(""""renderer":"none","amplitudeControl":true,"apiLevel":34.5"""))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "resonantFrequencyHz", caps(""""renderer":"none","amplitudeControl":true,"resonantFrequencyHz":-170"""))
        assertCapabilitiesRejected(RejectionReason.INVALID_VALUE, "renderer", caps(""""renderer":"Ampl!tude","amplitudeControl":true"""))
    }

    @Test
    fun decodeInbox_everyRejection_carriesAOneLineDetail() {
        val decoded = MessageCodec.decodeInbox(messageJson(sender = "\"line\\nbreak and a very long name that goes on and on\"").toByteArray())
        assertEquals(
            Decoded.Rejected(RejectionReason.INVALID_VALUE, "sender", "not a valid user name: \"line\\u000abreak and a very long name that goe…\""),
            decoded,
        )
    }

    @Test
    fun encode_nonAsciiText_writesUtf8() {
        val bytes = MessageCodec.encode(ChatMessage(ID_1, "a", 1, "é"))
        val expected = """{"schema":"hapticon.message","version":1,"id":"$ID_1","sender":"a","sentAt":1,"text":"é","sticker":null,"icon":null}"""
        assertArrayEquals(expected.toByteArray(Charsets.UTF_8), bytes)
    }

    private fun messageJson(
        version: String? = "1",
        id: String? = "\"$ID_1\"",
        sender: String? = "\"alice\"",
        sentAt: String? = "1767225600000",
        text: String? = "\"hi\"",
        extra: String = "",
    ): String {
        val members = listOfNotNull(
            "\"schema\":\"hapticon.message\"",
            version?.let { "\"version\":$it" },
            id?.let { "\"id\":$it" },
            sender?.let { "\"sender\":$it" },
            sentAt?.let { "\"sentAt\":$it" },
            text?.let { "\"text\":$it" },
        )
        return "{" + members.joinToString(",") + extra + "}"
    }

    private fun assertRejected(reason: RejectionReason, field: String?, json: String) = assertRejected(reason, field, json.toByteArray())

    private fun assertRejected(reason: RejectionReason, field: String?, payload: ByteArray) {
        val decoded = MessageCodec.decodeInbox(payload)
        val shown = String(payload.copyOf(minOf(payload.size, 200)), Charsets.UTF_8)
        val rejected = decoded as? Decoded.Rejected ?: throw AssertionError("expected $reason for $shown, got $decoded")
        assertEquals("reason for $shown (${rejected.detail})", reason, rejected.reason)
        assertEquals("field for $shown (${rejected.detail})", field, rejected.field)
    }

    private fun assertCapabilitiesRejected(reason: RejectionReason, field: String, json: String) {
        val rejected = MessageCodec.decodeCapabilities(json.toByteArray()) as Decoded.Rejected
        assertEquals(json, reason to field, rejected.reason to rejected.field)
    }
}
