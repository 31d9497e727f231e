package org.hapticon.companion.study

import org.hapticon.study.export.Csv
import org.hapticon.study.export.CsvFormatException
import org.hapticon.study.export.CsvRecord
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class CsvTest {
    @Test fun parsesQuotesEscapesCrlfAndMultilineFields() {
        val records = Csv.parse("a,b,c\r\n\"x, y\",\"say \"\"hi\"\"\",\r\n\"two\nlines\",2,3\n\n4,5,6", "f.csv")
        assertEquals(listOf(1, 2, 3, 6), records.map { it.line })
        assertEquals(listOf("x, y", "say \"hi\"", ""), records[1].fields)
        assertEquals(listOf("two\nlines", "2", "3"), records[2].fields)
        assertEquals(listOf("4", "5", "6"), records[3].fields)
    }

    @Test fun neutralise_formulaStarts_prefixedWithQuote_plainNumbersAndOtherTextUnchanged() {
        // OWASP CSV Injection: = + - @ tab CR at the start of a cell.
        for (formula in listOf("=1+1", "+1+1", "-1+1", "@SUM(A1)", "\tx", "\rx", "=", "-", "+", "@", "-e", "1e5x".let { "-$it" })) {
            assertEquals(formula, "'$formula", SpreadsheetCsv.neutralise(formula))
        }
        for (plain in listOf("", "-1", "+2.5", "-0.5e-3", ".5", "-.5", "3.", "1E10", "a=1", " =1", "'=1", "stroke", "\u2212" + "1")) {
            assertEquals(plain, plain, SpreadsheetCsv.neutralise(plain))
        }
        assertEquals("'=HYPERLINK(\"http://x\")", Csv.parse(SpreadsheetCsv.line(listOf("=HYPERLINK(\"http://x\")")), "f").single().fields.single())
        assertEquals("\"'=1,2\",-3\n", SpreadsheetCsv.line(listOf("=1,2", "-3")))
    }

    @Test fun skipsByteOrderMark() {
        assertEquals(listOf("a", "b"), Csv.parse("\uFEFFa,b\n", "f").single().fields)
    }

    @Test fun errorsNameSourceAndLine() {
        val open = assertThrows(CsvFormatException::class.java) { Csv.parse("a\n\"b\n", "f.csv") }
        assertEquals("f.csv:2: unterminated quoted field", open.message)
        val after = assertThrows(CsvFormatException::class.java) { Csv.parse("a,b\n\"x\"y,1\n", "f.csv") }
        assertEquals("f.csv:2: unexpected character 'y' after a closing quote", after.message)
        val stray = assertThrows(CsvFormatException::class.java) { Csv.parse("a\nb\"c\n", "f.csv") }
        assertEquals("f.csv:2: quote inside an unquoted field", stray.message)
    }

    @Test fun writesFieldsThatParseBack() {
        val values = listOf("plain", "a,b", "q\"uote", "line\nbreak", "")
        assertEquals("plain,\"a,b\",\"q\"\"uote\",\"line\nbreak\",\n", SpreadsheetCsv.line(values))
        assertEquals(values, Csv.parse(SpreadsheetCsv.line(values), "f").single().fields)
    }

    @Test fun emptyTextHasNoRecords() {
        assertEquals(0, Csv.parse("", "f").size)
    }
}

class CsvStreamingTest {
    /** A Reader handing out one character per read, so every field, quote and CRLF straddles a refill. */
    private class OneCharReader(text: String) : java.io.Reader() {
        private val inner = java.io.StringReader(text)
        override fun read(buffer: CharArray, offset: Int, length: Int): Int = inner.read(buffer, offset, minOf(1, length))
        override fun close() = inner.close()
    }

    @Test fun forEachRecord_oneCharacterPerRead_readsAsParseDoes() {
        val text = "\uFEFFa,b,c\r\n\"x, y\",\"say \"\"hi\"\"\",\r\n\"two\nlines\",2,3\n\n4,5,6"
        val streamed = ArrayList<CsvRecord>()
        Csv.forEachRecord(OneCharReader(text), "f.csv") { streamed += it }
        val parsed = Csv.parse(text, "f.csv")
        assertEquals(parsed.map { it.line to it.fields }, streamed.map { it.line to it.fields })
        assertEquals(listOf(1, 2, 3, 6), streamed.map { it.line })
    }

    @Test fun forEachRecord_errorAfterRecords_hasDeliveredTheEarlierOnesAndNamesTheLine() {
        val seen = ArrayList<List<String>>()
        val error = assertThrows(CsvFormatException::class.java) {
            Csv.forEachRecord(OneCharReader("a,b\n1,2\n\"open\n"), "f.csv") { seen += it.fields }
        }
        assertEquals("f.csv:3: unterminated quoted field", error.message)
        assertEquals(listOf(listOf("a", "b"), listOf("1", "2")), seen)
    }

    @Test fun forEachRecord_emptyInput_deliversNothing() {
        var count = 0
        Csv.forEachRecord(OneCharReader(""), "f.csv") { count++ }
        assertEquals(0, count)
    }
}
