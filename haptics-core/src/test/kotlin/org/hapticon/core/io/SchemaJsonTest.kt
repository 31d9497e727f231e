package org.hapticon.core.io

import kotlinx.serialization.Serializable
import kotlinx.serialization.ExperimentalSerializationApi
import kotlinx.serialization.json.JsonElement
import kotlinx.serialization.json.JsonNull
import kotlinx.serialization.json.JsonObject
import kotlinx.serialization.json.JsonPrimitive
import kotlinx.serialization.json.JsonUnquotedLiteral
import org.junit.Assert.assertEquals
import org.junit.Assert.assertNotSame
import org.junit.Assert.assertNull
import org.junit.Assert.assertSame
import org.junit.Assert.assertThrows
import org.junit.Test

class SchemaJsonTest {
    @Serializable
    class Item(val name: String, val weight: Double = 1.0)

    @Serializable
    class Doc(
        val schema: String,
        val count: Int,
        val big: Long = 0,
        val note: String? = null,
        val flags: List<Boolean> = emptyList(),
        val items: List<Item> = emptyList(),
        val extra: JsonElement? = null,
    )

    /** Records what [SchemaJson.check] reported, as text, and stops there. */
    private class TestReport : SchemaReport {
        val seen = ArrayList<String>()

        override fun notAnObject(path: String, value: JsonElement): Nothing = throw Problem("notAnObject($path, $value)")

        override fun wrongType(path: String, member: String, expected: JsonKind, value: JsonElement?): Nothing =
            throw Problem("wrongType($path, $member, $expected, $value)")

        override fun wrongElement(path: String, member: String, index: Int, expected: JsonKind, value: JsonElement): Nothing =
            throw Problem("wrongElement($path, $member, $index, $expected, $value)")

        override fun checked(path: String, member: String, value: JsonElement) {
            seen += "$path/$member=$value"
        }
    }

    private class Problem(message: String) : RuntimeException(message)

    private fun decode(text: String, report: TestReport = TestReport()): Doc =
        SchemaJson.decode(Doc.serializer(), Json.decode(text), report)

    private fun problem(text: String): String = assertThrows(Problem::class.java) { decode(text) }.message!!

    @Test
    fun decode_wholeNumberWithFraction_isReadAsAnInteger() {
        val doc = decode("""{"schema":"s","count":3.0,"big":1e15}""")
        assertEquals(3, doc.count)
        assertEquals(1_000_000_000_000_000L, doc.big)
    }

    @Test
    fun decode_nullOptionalMembers_takeTheirDefaults_unknownMembersIgnored() {
        val doc = decode("""{"schema":"s","count":1,"big":null,"note":null,"items":[{"name":"a","weight":null}],"future":[1]}""")
        assertEquals(0L, doc.big)
        assertEquals(null, doc.note)
        assertEquals(1.0, doc.items.single().weight, 0.0)
    }

    @Test
    fun check_missingOrNullRequiredMember_reportsItWithoutValue() {
        assertEquals("wrongType(, count, INT, null)", problem("""{"schema":"s"}"""))
        assertEquals("wrongType(, count, INT, null)", problem("""{"schema":"s","count":null}"""))
    }

    @Test
    fun check_wrongTypes_reportMemberKindAndValue() {
        assertEquals("wrongType(, count, INT, 2.5)", problem("""{"schema":"s","count":2.5}"""))
        assertEquals("wrongType(, count, INT, \"3\")", problem("""{"schema":"s","count":"3"}"""))
        assertEquals("wrongType(, count, INT, 2147483648)", problem("""{"schema":"s","count":2147483648}"""))
        assertEquals("wrongType(, big, LONG, 18014398509481984)", problem("""{"schema":"s","count":1,"big":18014398509481984}"""))
        assertEquals("wrongType(, schema, STRING, 1)", problem("""{"schema":1,"count":1}"""))
        assertEquals("wrongType(, items, ARRAY, {})", problem("""{"schema":"s","count":1,"items":{}}"""))
    }

    @Test
    fun check_intLimits_areAccepted() {
        assertEquals(Int.MAX_VALUE, decode("""{"schema":"s","count":2147483647}""").count)
        assertEquals(Int.MIN_VALUE, decode("""{"schema":"s","count":-2147483648}""").count)
    }

    @Test
    fun check_overflowingNumber_isReportedNotDecodedAsInfinity() {
        assertEquals("wrongType(items[0], weight, NUMBER, Infinity)", problem("""{"schema":"s","count":1,"items":[{"name":"a","weight":1e400}]}"""))
    }

    @Test
    fun check_badArrayElements_reportIndexAndPath() {
        assertEquals("wrongElement(, flags, 1, BOOLEAN, 0)", problem("""{"schema":"s","count":1,"flags":[true,0]}"""))
        assertEquals("notAnObject(items[1], 3)", problem("""{"schema":"s","count":1,"items":[{"name":"a"},3]}"""))
        assertEquals("wrongType(items[1], name, STRING, null)", problem("""{"schema":"s","count":1,"items":[{"name":"a"},{}]}"""))
    }

    @Test
    fun check_documentNotAnObject_reportsEmptyPath() {
        assertEquals("notAnObject(, [])", problem("[]"))
    }

    @Test
    fun check_membersAreReportedCheckedInSchemaOrder_beforeLaterProblems() {
        val report = TestReport()
        assertThrows(Problem::class.java) { decode("""{"count":"x","schema":"s"}""", report) }
        assertEquals(listOf("/schema=\"s\""), report.seen)
    }

    @Test
    fun check_jsonElementMember_isPassedThroughUnchecked() {
        val extra = decode("""{"schema":"s","count":1,"extra":{"any":[1,"two"]}}""").extra
        assertEquals("""{"any":[1,"two"]}""", extra.toString())
    }

    @Test
    fun encode_compactAndIndented() {
        val doc = Doc("s", 2, items = listOf(Item("a")))
        assertEquals("""{"schema":"s","count":2,"big":0,"note":null,"flags":[],"items":[{"name":"a","weight":1.0}],"extra":null}""", SchemaJson.encode(Doc.serializer(), doc))
        val lines = SchemaJson.encode(Item.serializer(), Item("a"), "\t").lines()
        assertEquals(listOf("{", "\t\"name\": \"a\",", "\t\"weight\": 1.0", "}"), lines)
        assertThrows(IllegalArgumentException::class.java) { SchemaJson.encode(Item.serializer(), Item("a"), "x") }
    }

    @Test
    fun strictReaderThenKotlinxWriter_keepsOrderAndIntegralForm() {
        val text = """{"z":1,"a":[2.5,-0.0,true,null,"s"],"m":{}}"""
        assertEquals(text, SchemaJson.encodeElement(Json.decode(text)))
    }

    @Test
    fun check_documentAlreadyInNormalForm_isReturnedItself() {
        val element = Json.decode("""{"schema":"s","count":3,"big":-9007199254740992,"note":null,"flags":[true],"items":[{"name":"a","weight":0.5}]}""")
        assertSame(element, SchemaJson.check(element, Doc.serializer().descriptor, "", TestReport()))
    }

    @Test
    fun check_membersToNormalise_giveACopyWithOnlyThoseChanged() {
        val element = Json.decode("""{"schema":"s","count":3.0,"items":[{"name":"a","weight":null},{"name":"b"}],"future":1}""")
        val checked = SchemaJson.check(element, Doc.serializer().descriptor, "", TestReport())
        assertNotSame(element, checked)
        assertEquals(
            Json.decode("""{"schema":"s","count":3,"items":[{"name":"a"},{"name":"b"}],"future":1}"""),
            checked,
        )
        // The input tree is left as it was.
        assertEquals(Json.decode("""{"schema":"s","count":3.0,"items":[{"name":"a","weight":null},{"name":"b"}],"future":1}"""), element)
    }

    @OptIn(ExperimentalSerializationApi::class)
    @Test
    fun check_integersOutsideTheExactRangeOrSpelledOtherwise_areNormalisedAsBefore() {
        fun checkedBig(value: JsonPrimitive): JsonElement? {
            val doc = JsonObject(mapOf("schema" to JsonPrimitive("s"), "count" to JsonPrimitive(1), "big" to value))
            return (SchemaJson.check(doc, Doc.serializer().descriptor, "", TestReport()) as JsonObject)["big"]
        }
        // ±2^53 are kept; one beyond reads as the double it rounds to, as the double path always read it.
        assertEquals(JsonPrimitive(9007199254740992L), checkedBig(JsonPrimitive(9007199254740992L)))
        assertEquals(JsonPrimitive(-9007199254740992L), checkedBig(JsonPrimitive(-9007199254740993L)))
        assertEquals(-9007199254740992L, decodeBig(JsonPrimitive(-9007199254740993L)))
        // Spellings the normal form changes: sign of zero, '+', exponent.
        assertEquals("0", checkedBig(JsonUnquotedLiteral("-0"))!!.let { (it as JsonPrimitive).content })
        assertEquals("5", checkedBig(JsonUnquotedLiteral("+5"))!!.let { (it as JsonPrimitive).content })
        assertEquals("100", checkedBig(JsonUnquotedLiteral("1e2"))!!.let { (it as JsonPrimitive).content })
        // Int limits on the kept path too.
        assertEquals("wrongType(, count, INT, 2147483648)", problem("""{"schema":"s","count":2147483648}"""))
        assertEquals("wrongType(, count, INT, -2147483649)", problem("""{"schema":"s","count":-2147483649}"""))
        assertEquals("wrongType(, count, INT, \"3\")", problem("""{"schema":"s","count":"3"}"""))
    }

    private fun decodeBig(value: JsonPrimitive): Long =
        SchemaJson.decode(Doc.serializer(), JsonObject(mapOf("schema" to JsonPrimitive("s"), "count" to JsonPrimitive(1), "big" to value)), TestReport()).big

    @OptIn(ExperimentalSerializationApi::class)
    @Test
    fun numberOrNull_readsNumbersAsDoubleOrNullDoes_andNothingElse() {
        assertEquals(3.0, JsonPrimitive(3).numberOrNull()!!, 0.0)
        assertEquals(0.27, JsonPrimitive(0.27).numberOrNull()!!, 0.0)
        assertEquals(1.2345678901234567E19, JsonUnquotedLiteral("12345678901234567890").numberOrNull()!!, 0.0)
        assertEquals(Double.POSITIVE_INFINITY, JsonUnquotedLiteral("1e400").numberOrNull()!!, 0.0)
        val negativeZero = JsonUnquotedLiteral("-0").numberOrNull()!!
        assertEquals(0.0, negativeZero, 0.0)
        assertEquals(-1.0 / 0.0, 1.0 / negativeZero, 0.0) // -0.0, as "-0".toDouble() gives
        assertNull(JsonPrimitive(true).numberOrNull())
        assertNull(JsonNull.numberOrNull())
        assertNull(JsonPrimitive("3").numberOrNull())
        assertNull(JsonUnquotedLiteral("1-2").numberOrNull())
    }
}
