package org.hapticon.core.io

import kotlinx.serialization.SerializationException
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import org.hapticon.core.HapticIcon
import org.hapticon.core.IconValidationException
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.fail
import org.junit.Test

class IconJsonTest {
    private val knockText =
        """{"schema":"hapticon.icon","version":1,"name":"knock","attack":0.005,"sustain":0.01,""" +
            """"level":0.5,"release":0.005,"note":57,"period":0.27,"count":3}"""

    private fun assertInvalid(text: String, field: String, message: String) {
        try {
            IconJson.decode(text)
            fail("accepted $text")
        } catch (e: IconValidationException) {
            assertEquals(field, e.field)
            assertEquals(message, e.message)
        }
    }

    /** The knock document with [member] replaced by [json], or removed when [json] is null. */
    private fun knockWith(member: String, json: String?): String {
        val value = Json.decode(knockText) as JsonObject
        val members = LinkedHashMap(value)
        if (json == null) members.remove(member) else members[member] = Json.decode(json)
        return SchemaJson.encodeElement(JsonObject(members))
    }

    @Test
    fun encode_knock_writesSchemaOrderAndShortNumbers() {
        assertEquals(knockText, IconJson.encode(HapticIcon.KNOCK))
    }

    @Test
    fun encode_hug_writesWholeNumbersWithoutFraction() {
        assertEquals(
            """{"schema":"hapticon.icon","version":1,"name":"hug","attack":1.5,"sustain":1,"level":0.5,""" +
                """"release":0.5,"note":50,"period":0,"count":1}""",
            IconJson.encode(HapticIcon.HUG),
        )
    }

    @Test
    fun encode_indented_isOneMemberPerLine() {
        val text = IconJson.encode(HapticIcon.HUG, indent = "  ")
        assertEquals(12, text.lines().size)
        assertEquals("  \"schema\": \"hapticon.icon\",", text.lines()[1])
        assertEquals(HapticIcon.HUG, IconJson.decode(text))
    }

    @Test
    fun decode_briefExample_isKnock() {
        val text = """{"schema": "hapticon.icon", "version": 1, "name": "knock", "attack": 0.005, "sustain": 0.01,
            "level": 0.5, "release": 0.005, "note": 57, "period": 0.27, "count": 3}"""
        assertEquals(HapticIcon.KNOCK, IconJson.decode(text))
    }

    @Test
    fun roundTrip_presetsAndAwkwardValues_areExact() {
        val awkward = HapticIcon("odd ✓ \"name\"", 0.1 + 0.2, 1.0 / 3, 0.7, 1e-9, 60.25, 0.123456789, 7)
        for (icon in HapticIcon.PRESETS + awkward) assertEquals(icon, IconJson.decode(IconJson.encode(icon)))
    }

    @Test
    fun decode_unknownMembers_areIgnored() {
        val text = knockText.replace("\"count\":3", "\"count\":3,\"colour\":\"red\",\"extra\":{\"deep\":[1]}")
        assertEquals(HapticIcon.KNOCK, IconJson.decode(text))
    }

    @Test
    fun decode_withoutPeriodAndCount_usesDefaults() {
        val text = knockWith("period", null).let { SchemaJson.encodeElement(JsonObject((Json.decode(it) as JsonObject) - "count")) }
        assertEquals(HapticIcon("knock", 0.005, 0.01, 0.5, 0.005, 57.0, period = 0.0, count = 1), IconJson.decode(text))
    }

    @Test
    fun decode_countWrittenAsWholeDouble_isAccepted() {
        assertEquals(HapticIcon.KNOCK, IconJson.decode(knockWith("count", "3.0")))
    }

    @Test
    fun decode_missingRequiredMembers_nameTheField() {
        for (field in listOf("name", "attack", "sustain", "level", "release", "note")) {
            assertInvalid(knockWith(field, null), field, "$field: missing")
        }
    }

    @Test
    fun decode_wrongTypes_nameTheFieldAndValue() {
        assertInvalid(knockWith("attack", "\"abc\""), "attack", "attack: expected a number, got \"abc\"")
        assertInvalid(knockWith("note", "[57]"), "note", "note: expected a number, got [57]")
        assertInvalid(knockWith("period", "null"), "period", "period: expected a number, got null")
        assertInvalid(knockWith("level", "true"), "level", "level: expected a number, got true")
        assertInvalid(knockWith("name", "5"), "name", "name: expected a string, got 5")
        assertInvalid(knockWith("count", "\"3\""), "count", "count: expected a number, got \"3\"")
    }

    @Test
    fun decode_longValueInError_isShortened() {
        val long = "x".repeat(100)
        assertInvalid(knockWith("sustain", "\"$long\""), "sustain", "sustain: expected a number, got \"${"x".repeat(39)}…")
    }

    @Test
    fun decode_overflowingNumber_isRejectedByName() {
        // Edited as text: the value model cannot encode infinity.
        val hugeAttack = knockText.replace("\"attack\":0.005", "\"attack\":1e400")
        assertInvalid(hugeAttack, "attack", "attack: expected a finite number, got a number too large for a double")
        val hugeNote = knockText.replace("\"note\":57", "\"note\":-1e400")
        assertInvalid(hugeNote, "note", "note: expected a finite number, got a number too small for a double")
    }

    @Test
    fun decode_outOfRangeValues_areRejectedByTheIconRules() {
        assertInvalid(knockWith("level", "2"), "level", "level: must be in [0, 1], was 2.0")
        assertInvalid(knockWith("attack", "-0.1"), "attack", "attack: must be a finite number of seconds >= 0, was -0.1")
        assertInvalid(knockWith("note", "128"), "note", "note: must be a MIDI note in [0, 127], was 128.0")
        assertInvalid(knockWith("name", "\"  \""), "name", "name: must be 1..64 characters, not blank")
        assertInvalid(knockWith("period", "0"), "period", "period: must be > 0 when count > 1, was 0.0")
    }

    @Test
    fun decode_badCounts_nameTheField() {
        assertInvalid(knockWith("count", "2.5"), "count", "count: expected an integer, got 2.5")
        assertInvalid(knockWith("count", "0"), "count", "count: must be in 1..64, was 0")
        assertInvalid(knockWith("count", "65"), "count", "count: must be in 1..64, was 65")
        assertInvalid(knockWith("count", "1e10"), "count", "count: must be in 1..64, was 10000000000")
        assertInvalid(knockWith("count", "1e300"), "count", "count: integer 1.0E300 is out of range")
    }

    @Test
    fun decode_newerVersion_isRejectedClearly() {
        assertInvalid(
            knockWith("version", "2"),
            "version",
            "version: unsupported icon schema version 2 (this build reads version 1)",
        )
    }

    @Test
    fun decode_badVersions_areRejected() {
        assertInvalid(knockWith("version", null), "version", "version: missing")
        assertInvalid(knockWith("version", "0"), "version", "version: unsupported icon schema version 0 (this build reads version 1)")
        assertInvalid(knockWith("version", "1.5"), "version", "version: expected an integer, got 1.5")
        assertInvalid(knockWith("version", "\"1\""), "version", "version: expected a number, got \"1\"")
    }

    @Test
    fun decode_versionIsCheckedBeforeOtherMembers() {
        val text = knockWith("version", "2").let { v -> SchemaJson.encodeElement(JsonObject((Json.decode(v) as JsonObject) - "attack")) }
        assertInvalid(text, "version", "version: unsupported icon schema version 2 (this build reads version 1)")
    }

    @Test
    fun decode_wrongOrMissingSchema_isRejected() {
        assertInvalid(knockWith("schema", "\"hapticon.message\""), "schema", "schema: expected \"hapticon.icon\", got \"hapticon.message\"")
        assertInvalid(knockWith("schema", null), "schema", "schema: missing; expected \"hapticon.icon\"")
    }

    @Test
    fun decode_notAnObject_isRejected() {
        assertInvalid("[1,2]", "icon", "icon: expected an object, got [1,2]")
    }

    @Test
    fun decode_malformedJson_throwsJsonException() {
        try {
            IconJson.decode(knockText.dropLast(1))
            fail()
        } catch (e: JsonException) {
            assertEquals(knockText.length - 1, e.offset)
        }
    }

    @Test
    fun jsonElement_embeddedInAMessage_roundTrips() {
        val message = JsonObject(linkedMapOf("from" to JsonPrimitive("ana"), "icon" to IconJson.toJsonElement(HapticIcon.HIT)))
        val received = Json.decode(SchemaJson.encodeElement(message)) as JsonObject
        assertEquals(HapticIcon.HIT, IconJson.fromJsonElement(received["icon"]!!))
    }

    @Test
    fun list_presets_roundTrip() {
        val text = IconJson.encodeList(HapticIcon.PRESETS)
        assertEquals('[', text.first())
        assertEquals(HapticIcon.PRESETS, IconJson.decodeList(text))
        assertEquals(emptyList<HapticIcon>(), IconJson.decodeList("[]"))
        // As the hand-written writer spelled it: one member per line, whole numbers without a fraction.
        val pretty = IconJson.encodeList(HapticIcon.PRESETS.take(1), indent = "  ").lines()
        assertEquals(listOf("[", "  {", "    \"schema\": \"hapticon.icon\","), pretty.take(3))
        assertEquals(listOf("    \"count\": ${HapticIcon.PRESETS[0].count}", "  }", "]"), pretty.takeLast(3))
    }

    @Test
    fun decodeList_badElement_namesIndexAndField() {
        val text = "[$knockText,${knockWith("attack", "\"abc\"")}]"
        try {
            IconJson.decodeList(text)
            fail()
        } catch (e: IconValidationException) {
            assertEquals("icons[1].attack", e.field)
            assertEquals("icons[1].attack: expected a number, got \"abc\"", e.message)
        }
    }

    @Test
    fun decodeList_notAnArray_isRejected() {
        try {
            IconJson.decodeList(knockText)
            fail()
        } catch (e: IconValidationException) {
            assertEquals("icons", e.field)
            assertEquals("icons: expected an array, got {\"schema\":\"hapticon.icon\",\"version\":1,\"n…", e.message)
        }
    }

    @Test
    fun decodeList_elementNotAnObject_namesIndex() {
        try {
            IconJson.decodeList("[$knockText,3]")
            fail()
        } catch (e: IconValidationException) {
            assertEquals("icons[1].icon: expected an object, got 3", e.message)
        }
    }

    @Test
    fun hapticIconSerializer_writesWhatEncodeWrites_andReadsWithIconJsonsWording() {
        val text = SchemaJson.format.encodeToString(HapticIconSerializer, HapticIcon.KNOCK)
        assertEquals(
            """{"schema":"hapticon.icon","version":1,"name":"knock","attack":0.005,"sustain":0.01,"level":0.5,"release":0.005,"note":57,"period":0.27,"count":3}""",
            text,
        )
        assertEquals(IconJson.encode(HapticIcon.KNOCK), text)
        assertEquals(HapticIcon.KNOCK, SchemaJson.format.decodeFromString(HapticIconSerializer, text))
        // kotlinx 1.12's string decoder wraps what a serializer throws (with the path); the cause is IconJson's own.
        val wrapped = assertThrows(SerializationException::class.java) {
            SchemaJson.format.decodeFromString(HapticIconSerializer, text.replace("\"attack\":0.005", "\"attack\":\"x\""))
        }
        val e = wrapped.cause as IconValidationException
        assertEquals("attack", e.field)
        assertEquals("attack: expected a number, got \"x\"", e.message)
    }
}
