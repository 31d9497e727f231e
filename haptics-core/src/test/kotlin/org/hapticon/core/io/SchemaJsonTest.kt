package org.hapticon.core.io

import kotlinx.serialization.Serializable
import kotlinx.serialization.json.JsonElement
import org.junit.Assert.assertEquals
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
}
