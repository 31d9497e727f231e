package org.hapticon.core.io

import kotlinx.serialization.json.JsonArray
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.double
import kotlinx.serialization.json.jsonPrimitive
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import kotlin.random.Random

/** The strict reader ([Json], [JsonReader]): it builds kotlinx [kotlinx.serialization.json.JsonElement]s. */
class JsonTest {
    // ---- decoding: values ----

    @Test
    fun decode_object_keepsMemberOrder() {
        val value = Json.decode("""{"b": 1, "a": 2, "c": 3}""") as JsonObject
        assertEquals(listOf("b", "a", "c"), value.keys.toList())
        assertEquals(JsonPrimitive(2), value["a"])
    }

    @Test
    fun decode_everyKind_buildsTheValueTree() {
        val value = Json.decode(""" {"s":"x","n":-12,"f":2.5e-1,"t":true,"u":false,"z":null,"a":[[],{}]} """)
        val expected = JsonObject(
            linkedMapOf(
                "s" to JsonPrimitive("x"),
                "n" to JsonPrimitive(-12),
                "f" to JsonPrimitive(0.25),
                "t" to JsonPrimitive(true),
                "u" to JsonPrimitive(false),
                "z" to JsonNull,
                "a" to JsonArray(listOf(JsonArray(emptyList()), JsonObject(emptyMap()))),
            ),
        )
        assertEquals(expected, value)
        assertEquals(expected.toString(), value.toString()) // same spelling: integers stay integers
    }

    @Test
    fun decode_topLevelScalarsAndWhitespace_areAccepted() {
        assertEquals(JsonPrimitive("x"), Json.decode(" \t\n\r\"x\"\r\n"))
        assertEquals(JsonNull, Json.decode("null"))
        assertEquals(JsonPrimitive(true), Json.decode("true"))
        assertEquals(JsonPrimitive(0), Json.decode("0"))
    }

    @Test
    fun decode_numberForms_recordWhetherIntegral() {
        // A literal without fraction or exponent is an integer; anything else a double, spelled by Double.toString.
        assertEquals("3", (Json.decode("3") as JsonPrimitive).content)
        assertEquals("3.0", (Json.decode("3.0") as JsonPrimitive).content)
        assertEquals("3.0", (Json.decode("3e0") as JsonPrimitive).content)
        assertEquals("-0.5", (Json.decode("-5E-1") as JsonPrimitive).content)
        assertEquals("1200.0", (Json.decode("1.2e+3") as JsonPrimitive).content)
        assertFalse((Json.decode("3") as JsonPrimitive).isString)
    }

    @Test
    fun decode_negativeZeroInteger_isZero() {
        // As the tree conversion of earlier builds did (an integer has no sign of zero); "-0.0" keeps it.
        assertEquals(JsonPrimitive(0), Json.decode("-0"))
        assertEquals((-0.0).toRawBits(), Json.decode("-0.0").jsonPrimitive.double.toRawBits())
    }

    @Test
    fun decode_integerBeyondLong_becomesNearestDouble() {
        assertEquals(JsonPrimitive(1.2345678901234567E19), Json.decode("12345678901234567890"))
        assertEquals(JsonPrimitive(9007199254740992L), Json.decode("9007199254740993")) // the nearest double, 2^53
    }

    @Test
    fun decode_overflowingNumber_isInfinite() {
        assertEquals(Double.POSITIVE_INFINITY, Json.decode("1e400").jsonPrimitive.double, 0.0)
        assertEquals(Double.NEGATIVE_INFINITY, Json.decode("-1e400").jsonPrimitive.double, 0.0)
        assertEquals(Double.POSITIVE_INFINITY, Json.decode("1" + "0".repeat(400)).jsonPrimitive.double, 0.0)
        assertEquals(0.0, Json.decode("1e-400").jsonPrimitive.double, 0.0)
        // kept, not thrown, so that a schema check can name the member; snippets spell it out
        assertEquals("a number too large for a double", snippet(Json.decode("1e400")))
        assertEquals("a number too small for a double", snippet(Json.decode("-1e400")))
    }

    @Test
    fun decode_shortDecimals_matchTheGeneralConversionExactly() {
        val random = Random(7)
        repeat(50_000) {
            val digits = random.nextLong(1, 10_000_000_000_000_000L).toString()
            val point = random.nextInt(0, digits.length + 1)
            val exponent = random.nextInt(-30, 31)
            val text = (if (random.nextBoolean()) "-" else "") + digits.substring(0, point).ifEmpty { "0" } +
                (if (point < digits.length) "." + digits.substring(point) else "") + "e$exponent"
            val decoded = Json.decode(text).jsonPrimitive.double
            assertEquals(text, text.toDouble().toRawBits(), decoded.toRawBits())
        }
    }

    @Test
    fun decode_fastPathBoundaries_matchTheGeneralConversion() {
        val texts = listOf(
            "9007199254740992", "9007199254740993", "-9007199254740993", "999999999999999999", "1000000000000000000",
            "1e22", "1e23", "3e-22", "3e-23", "0.1", "0.3", "2.2250738585072014e-308", "4.9e-324", "1.7976931348623157e308",
            "0.000000000000000000000000000001", "123456789012345678.5", "1" + "0".repeat(400) + "e-400", "0e999999999",
        )
        for (text in texts) assertEquals(text, text.toDouble().toRawBits(), Json.decode(text).jsonPrimitive.double.toRawBits())
    }

    @Test
    fun decode_everyEscape_isResolved() {
        val value = Json.decode(""""\"\\\/\b\f\n\r\t\u0041\u00e9\u00E9"""")
        assertEquals(JsonPrimitive("\"\\/\b\u000C\n\r\tAéé"), value)
    }

    @Test
    fun decode_escapedSurrogatePair_combinesIntoOneCodePoint() {
        val value = (Json.decode(""""\uD83D\uDE00"""") as JsonPrimitive).content
        assertEquals("\uD83D\uDE00", value)
        assertEquals(0x1F600, value.codePointAt(0))
    }

    @Test
    fun decode_rawNonAsciiAndSurrogatePair_areKept() {
        assertEquals(JsonPrimitive("é😀ü"), Json.decode("\"é😀ü\""))
    }

    @Test
    fun decode_escapedHighAndRawLowSurrogate_combine() {
        assertEquals(JsonPrimitive("\uD83D\uDE00"), Json.decode("\"\\uD83D\uDE00\""))
    }

    @Test
    fun decode_deepestAllowedNesting_succeeds() {
        val text = "[".repeat(Json.DEFAULT_MAX_DEPTH) + "]".repeat(Json.DEFAULT_MAX_DEPTH)
        var value = Json.decode(text)
        var depth = 0
        while (value is JsonArray && value.size > 0) {
            value = value[0]
            depth++
        }
        assertEquals(Json.DEFAULT_MAX_DEPTH - 1, depth)
    }

    @Test
    fun decode_customMaxDepth_allowsDeeperDocuments() {
        val text = "[".repeat(300) + "]".repeat(300)
        assertTrue(Json.decode(text, maxDepth = 300) is JsonArray)
    }

    // ---- decoding: errors ----

    private fun assertRejected(text: String, offset: Int, messageStart: String, maxLength: Int = Json.DEFAULT_MAX_LENGTH) {
        try {
            Json.decode(text, maxLength = maxLength)
            fail("accepted ${text.take(40)}")
        } catch (e: JsonException) {
            assertEquals("offset for ${text.take(40)}: ${e.message?.take(200)}", offset, e.offset)
            assertTrue("message for ${text.take(40)}: ${e.message?.take(200)}", e.message!!.startsWith(messageStart))
            assertTrue(e.message!!.endsWith(" at offset $offset"))
        }
    }

    @Test
    fun decode_emptyInput_failsAtTheEnd() {
        assertRejected("", 0, "unexpected end of input, expected a value")
        assertRejected("   ", 3, "unexpected end of input, expected a value")
    }

    @Test
    fun decode_trailingGarbage_isRejected() {
        assertRejected("{} x", 3, "unexpected 'x' after the JSON value")
        assertRejected("1 2", 2, "unexpected '2' after the JSON value")
        assertRejected("nullx", 4, "unexpected 'x' after the JSON value")
    }

    @Test
    fun decode_malformedNumbers_areRejected() {
        assertRejected("01", 1, "leading zeros are not allowed")
        assertRejected("-01", 2, "leading zeros are not allowed")
        assertRejected("-", 1, "unexpected end of input, expected a digit")
        assertRejected("1.", 2, "unexpected end of input, expected a digit after '.'")
        assertRejected("1.e5", 2, "unexpected 'e', expected a digit after '.'")
        assertRejected("1e", 2, "unexpected end of input, expected a digit in the exponent")
        assertRejected("1e+", 3, "unexpected end of input, expected a digit in the exponent")
        assertRejected(".5", 0, "unexpected '.', expected a value")
        assertRejected("+1", 0, "unexpected '+', expected a value")
        assertRejected("NaN", 0, "unexpected 'N', expected a value")
        assertRejected("Infinity", 0, "unexpected 'I', expected a value")
        assertRejected("-Infinity", 1, "unexpected 'I', expected a digit")
        assertRejected("0x10", 1, "unexpected 'x' after the JSON value")
    }

    @Test
    fun decode_malformedLiterals_areRejected() {
        assertRejected("tru", 0, "invalid literal, expected 'true'")
        assertRejected("nul", 0, "invalid literal, expected 'null'")
        assertRejected("False", 0, "unexpected 'F', expected a value")
    }

    @Test
    fun decode_malformedContainers_areRejected() {
        assertRejected("[1,]", 3, "unexpected ']', expected a value")
        assertRejected("[1 2]", 3, "unexpected '2', expected ',' or ']'")
        assertRejected("[1,", 3, "unexpected end of input, expected a value")
        assertRejected("[", 1, "unexpected end of input, expected a value")
        assertRejected("{\"a\":1,}", 7, "unexpected '}', expected a member name in double quotes")
        assertRejected("{a:1}", 1, "unexpected 'a', expected a member name in double quotes")
        assertRejected("{\"a\" 1}", 5, "unexpected '1', expected ':'")
        assertRejected("{\"a\":1 \"b\":2}", 7, "unexpected '\"', expected ',' or '}'")
        assertRejected("{\"a\":1", 6, "unexpected end of input, expected ',' or '}'")
        assertRejected("]", 0, "unexpected ']', expected a value")
    }

    @Test
    fun decode_duplicateMemberName_isRejectedAtTheSecondName() {
        assertRejected("""{"a":1,"a":2}""", 7, "duplicate member name \"a\"")
    }

    @Test
    fun decode_malformedStrings_areRejected() {
        assertRejected("\"abc", 0, "unterminated string")
        assertRejected("\"a\u0001\"", 2, "unescaped control character U+0001 in string")
        assertRejected("\"a\nb\"", 2, "unescaped control character U+000A in string")
        assertRejected("\"\\x\"", 2, "invalid escape 'x'")
        assertRejected("\"\\", 2, "unterminated escape")
        assertRejected("\"\\u12G4\"", 5, "invalid hex digit 'G' in \\u escape")
        assertRejected("\"\\u12", 3, "unterminated \\u escape")
    }

    @Test
    fun decode_unpairedSurrogates_areRejected() {
        assertRejected("\"\\uD83D\"", 7, "unpaired surrogate in string") // high, then the closing quote
        assertRejected("\"\\uD83Dx\"", 7, "unpaired surrogate in string") // high, then a plain character
        assertRejected("\"\\uDE00\"", 1, "unpaired surrogate in string") // low without high
        assertRejected("\"\uDE00\"", 1, "unpaired surrogate in string") // raw low
        assertRejected("\"\\uD83D\\uD83D\"", 7, "unpaired surrogate in string") // two highs
    }

    @Test
    fun decode_byteOrderMark_isRejected() {
        assertRejected("\uFEFF{}", 0, "unexpected U+FEFF, expected a value")
    }

    @Test
    fun decode_nestingBeyondMaxDepth_isRejectedWithoutStackOverflow() {
        val justTooDeep = "[".repeat(Json.DEFAULT_MAX_DEPTH + 1) + "]".repeat(Json.DEFAULT_MAX_DEPTH + 1)
        assertRejected(justTooDeep, Json.DEFAULT_MAX_DEPTH, "nesting deeper than 64 levels")
        // Two containers per 6-character unit: the 65th container opens at 32 · 6.
        assertRejected("[{\"a\":".repeat(100_000), 192, "nesting deeper than 64 levels")
    }

    @Test
    fun decode_inputLongerThanMaxLength_isRejectedBeforeParsing() {
        assertRejected("[1]", 2, "input of 3 characters exceeds the limit of 2", maxLength = 2)
        assertEquals(JsonArray(listOf(JsonPrimitive(1))), Json.decode("[1]", maxLength = 3))
    }

    @Test
    fun decode_invalidLimits_throwIllegalArgument() {
        for (call in listOf<() -> Unit>({ Json.decode("1", maxDepth = 0) }, { Json.decode("1", maxDepth = 513) }, { Json.decode("1", maxLength = -1) })) {
            try {
                call()
                fail("accepted an invalid limit")
            } catch (e: IllegalArgumentException) {
                assertFalse(e is JsonException)
            }
        }
    }

    @Test
    fun decodeUtf8_validBytes_decode() {
        assertEquals(JsonObject(mapOf("é" to JsonPrimitive("😀"))), Json.decodeUtf8("{\"é\":\"😀\"}".toByteArray()))
    }

    @Test
    fun decodeUtf8_replacementCharacterInTheInput_isKept() {
        // U+FFFD is also what lenient decoding puts in place of malformed bytes; written in the input, it is text.
        assertEquals(JsonPrimitive("a\uFFFDb"), Json.decodeUtf8("\"a\uFFFDb\"".toByteArray()))
    }

    @Test
    fun decodeUtf8_malformedSequenceAfterAReplacementCharacter_isRejectedAtItsByteOffset() {
        val bytes = "\"\uFFFD".toByteArray() + byteArrayOf(0xE2.toByte(), 0x28, '"'.code.toByte())
        val e = assertThrows(JsonException::class.java) { Json.decodeUtf8(bytes) }
        assertEquals(4, e.offset)
        assertEquals("malformed UTF-8 at offset 4", e.message)
    }

    @Test
    fun decodeUtf8_malformedSequence_isRejectedAtItsByteOffset() {
        val bytes = byteArrayOf('"'.code.toByte(), 'a'.code.toByte(), 0xC3.toByte(), 0x28, '"'.code.toByte())
        try {
            Json.decodeUtf8(bytes)
            fail()
        } catch (e: JsonException) {
            assertEquals(2, e.offset)
            assertEquals("malformed UTF-8 at offset 2", e.message)
        }
    }

    @Test
    fun decodeUtf8_encodedSurrogate_isRejected() {
        // CESU-style encoding of U+D800 is not valid UTF-8.
        val bytes = byteArrayOf('"'.code.toByte(), 0xED.toByte(), 0xA0.toByte(), 0x80.toByte(), '"'.code.toByte())
        try {
            Json.decodeUtf8(bytes)
            fail()
        } catch (e: JsonException) {
            assertEquals(1, e.offset)
        }
    }

    @Test
    fun decodeUtf8_tooManyBytes_isRejected() {
        try {
            Json.decodeUtf8("\"éé\"".toByteArray(), maxLength = 5)
            fail()
        } catch (e: JsonException) {
            assertEquals("input of 6 bytes exceeds the limit of 5 at offset 5", e.message)
        }
    }

    // ---- round trips through kotlinx's writer ----

    @Test
    fun roundTrip_randomDoubles_areBitExact() {
        val random = Random(42)
        repeat(20_000) {
            val value = Double.fromBits(random.nextLong())
            if (value.isFinite()) {
                val decoded = Json.decode(SchemaJson.encodeElement(JsonPrimitive(value))).jsonPrimitive.double
                assertEquals(value.toRawBits(), decoded.toRawBits())
            }
        }
    }

    @Test
    fun roundTrip_everyCharacter_survives() {
        val builder = StringBuilder()
        for (c in 0..0xFFFF) if (c !in 0xD800..0xDFFF) builder.append(c.toChar())
        builder.append("\uD800\uDC00\uDBFF\uDFFF")
        val text = builder.toString()
        assertEquals(JsonPrimitive(text), Json.decode(SchemaJson.encodeElement(JsonPrimitive(text))))
        assertEquals(JsonPrimitive(text), Json.decodeUtf8(SchemaJson.encodeElement(JsonPrimitive(text)).toByteArray()))
    }

    @Test
    fun roundTrip_document_isIdentical() {
        val text = """{"schema":"x","list":[1,2.5,-0.001,true,false,null,"é\n"],"nested":{"a":{"b":[]}}}"""
        assertEquals(text, SchemaJson.encodeElement(Json.decode(text)))
        val pretty = SchemaJson.encodeElement(Json.decode(text), indent = "\t")
        assertEquals(Json.decode(text), Json.decode(pretty))
    }

    @Test
    fun decodedObject_equality_ignoresOrder() {
        assertEquals(Json.decode("""{"a":1,"b":2}"""), Json.decode("""{"b":2,"a":1}"""))
    }

    @Test
    fun snippet_cutsLongValuesAndEscapesStrings() {
        assertEquals("\"a\\n\\\"\"", snippet(JsonPrimitive("a\n\"")))
        assertEquals("[" + "1,".repeat(19) + "1…", snippet(Json.decode("[" + "1,".repeat(40) + "1]")))
    }
}
