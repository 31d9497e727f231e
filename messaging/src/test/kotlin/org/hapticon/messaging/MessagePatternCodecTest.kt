package org.hapticon.messaging

import org.hapticon.core.HapticIcon
import org.hapticon.core.pattern.AmplitudeKey
import org.hapticon.core.pattern.FrequencyKey
import org.hapticon.core.pattern.HapticPattern
import org.hapticon.core.pattern.Transient
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertTrue
import org.junit.Test

class MessagePatternCodecTest {
    private val boing = HapticPattern(
        "boing",
        listOf(AmplitudeKey(0.0, 0.0), AmplitudeKey(0.05, 1.0), AmplitudeKey(0.4, 0.0)),
        listOf(FrequencyKey(0.0, 220.0), FrequencyKey(0.4, 110.0)),
        listOf(Transient(0.1, 0.8, 0.4)),
    )

    @Test
    fun encode_messageWithPattern_writesVersionTwoWithThePatternJson() {
        val message = ChatMessage(ID_1, "alice", 5, "boing", pattern = boing)
        val expected = """{"schema":"hapticon.message","version":2,"id":"$ID_1","sender":"alice","sentAt":5,"text":"boing",""" +
            """"sticker":null,"icon":null,"pattern":{"schema":"hapticon.pattern","version":1,"name":"boing",""" +
            """"amplitude":[{"time":0,"amplitude":0},{"time":0.05,"amplitude":1},{"time":0.4,"amplitude":0}],""" +
            """"frequency":[{"time":0,"hertz":220},{"time":0.4,"hertz":110}],""" +
            """"transients":[{"time":0.1,"intensity":0.8,"sharpness":0.4}]}}"""
        assertEquals(expected, String(MessageCodec.encode(message), Charsets.UTF_8))
        assertEquals(Decoded.Accepted(message), MessageCodec.decodeInbox(MessageCodec.encode(message)))
    }

    @Test
    fun encode_messageWithIconOnly_staysVersionOneForOlderBuilds() {
        val bytes = MessageCodec.encode(ChatMessage(ID_1, "alice", 5, "", icon = HapticIcon.HIT))
        assertTrue(String(bytes, Charsets.UTF_8).startsWith("""{"schema":"hapticon.message","version":1,"""))
        assertTrue("no pattern member", !String(bytes, Charsets.UTF_8).contains("pattern"))
    }

    @Test
    fun decodeInbox_versionThree_rejectedNamingTheVersionsThisBuildReads() {
        val rejected = MessageCodec.decodeInbox(
            """{"schema":"hapticon.message","version":3,"id":"$ID_1","sender":"a","sentAt":1,"text":"x"}""".toByteArray(),
        ) as Decoded.Rejected
        assertEquals(RejectionReason.UNSUPPORTED_VERSION, rejected.reason)
        assertEquals("this build reads versions 1–2 of \"hapticon.message\", got 3", rejected.detail)
    }

    @Test
    fun decodeInbox_receiptVersionTwo_stillRejected() {
        val rejected = MessageCodec.decodeInbox(
            """{"schema":"hapticon.receipt","version":2,"messageId":"$ID_1","from":"b","state":"read","at":1}""".toByteArray(),
        ) as Decoded.Rejected
        assertEquals("this build reads version 1 of \"hapticon.receipt\", got 2", rejected.detail)
    }

    @Test
    fun decodeInbox_hostilePatterns_rejectedNamingTheMember() {
        fun pattern(amplitude: String, frequency: String = """[{"time":0,"hertz":150}]""", schema: String = "hapticon.pattern") =
            """{"schema":"hapticon.message","version":2,"id":"$ID_1","sender":"a","sentAt":1,"text":"",""" +
                """"pattern":{"schema":"$schema","version":1,"name":"p","amplitude":$amplitude,"frequency":$frequency}}"""
        val cases = mapOf(
            pattern("""[{"time":0,"amplitude":1e400}]""") to "pattern.amplitude[0].amplitude",
            pattern("""[{"time":-1,"amplitude":0.5}]""") to "pattern.amplitude[0].time",
            pattern("""[{"time":0,"amplitude":0.5},{"time":1e300,"amplitude":0.5}]""") to "pattern.duration",
            pattern("""[{"time":0.5,"amplitude":0.5},{"time":0.25,"amplitude":0.5}]""") to "pattern.amplitude[1].time",
            pattern("""[]""", frequency = """[{"time":0,"hertz":0}]""") to "pattern.frequency[0].hertz",
            pattern("""[]""", schema = "hapticon.icon") to "pattern.schema",
        )
        for ((json, field) in cases) {
            val rejected = MessageCodec.decodeInbox(json.toByteArray()) as? Decoded.Rejected ?: throw AssertionError("accepted $json")
            assertEquals(json, field, rejected.field)
            assertTrue(rejected.detail, !rejected.detail.contains('\n'))
        }
    }

    @Test
    fun decodeInbox_patternOverTheMessageLimits_rejected() {
        // 20 s is a valid pattern (under the 30 s cap) but longer than a message may play.
        val long = """{"time":0,"amplitude":0.5},{"time":20,"amplitude":0.5}"""
        val json = """{"schema":"hapticon.message","version":2,"id":"$ID_1","sender":"a","sentAt":1,"text":"",""" +
            """"pattern":{"schema":"hapticon.pattern","version":1,"name":"p","amplitude":[$long],"frequency":[{"time":0,"hertz":150}]}}"""
        val rejected = MessageCodec.decodeInbox(json.toByteArray()) as Decoded.Rejected
        assertEquals(RejectionReason.ICON_TOO_LONG to "pattern", rejected.reason to rejected.field)
    }

    @Test
    fun chatMessage_iconAndPatternOrTooManyKeys_throwsNamingThePattern() {
        val both = assertThrows(InvalidMessageException::class.java) { ChatMessage(ID_1, "a", 1, "", icon = HapticIcon.HIT, pattern = boing) }
        assertEquals("pattern", both.field)
        val keys = (0 until MessageLimits.MAX_PATTERN_KEYS).map { AmplitudeKey(it * 0.001, 0.5) }
        val many = HapticPattern("many", keys, listOf(FrequencyKey(0.0, 150.0)))
        val tooMany = assertThrows(InvalidMessageException::class.java) { ChatMessage(ID_1, "a", 1, "", pattern = many) }
        assertEquals("has 361 keys and taps, more than the 360 a message may", tooMany.message!!.removePrefix("pattern: "))
    }

    @Test
    fun encode_largestValidPatternMessage_fitsThePayloadLimit() {
        // The widest numbers Double.toString writes (17 significant digits and an exponent) in every member,
        // the most taps a message may carry, and a text of 4000 characters that must each be escaped as \uXXXX.
        val ugly = 1.2345678901234567E-4
        val taps = (0 until MessageLimits.MAX_PATTERN_KEYS - 1).map { Transient(it * 0.01 + ugly, 0.12345678901234567, 0.12345678901234567) }
        val pattern = HapticPattern("x".repeat(HapticIcon.MAX_NAME_LENGTH), emptyList(), listOf(FrequencyKey(ugly, 123.45678901234567)), taps)
        val message = ChatMessage(ID_1, "a".repeat(32), MessageLimits.MAX_TIMESTAMP_MILLIS, "\u0001".repeat(MessageLimits.MAX_TEXT_LENGTH), pattern = pattern)
        val bytes = MessageCodec.encode(message)
        assertTrue("${bytes.size} bytes", bytes.size <= MessageLimits.MAX_PAYLOAD_BYTES)
        assertEquals(Decoded.Accepted(message), MessageCodec.decodeInbox(bytes))
    }
}
