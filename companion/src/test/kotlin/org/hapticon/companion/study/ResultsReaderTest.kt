package org.hapticon.companion.study

import org.hapticon.study.analysis.StudyResponse
import org.hapticon.study.export.CsvFormatException
import org.hapticon.testing.StudyResults
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class ResultsReaderTest {
    @Test fun readsTheExampleInAnyColumnOrder() {
        val responses = ResultsReader.read(StudyResults.exampleCsv(), "example.csv")
        assertEquals(29, responses.size)
        assertEquals(StudyResponse("P01", "calm", "stroke", 4.0), responses[0])
        val reordered = ResultsReader.read("response,extra,icon,task,participant\n3.5,x,hug,calm,P9\n", "r.csv")
        assertEquals(listOf(StudyResponse("P9", "calm", "hug", 3.5)), reordered)
    }

    @Test fun problemsNameFileAndLine() {
        fun message(text: String) = assertThrows(CsvFormatException::class.java) { ResultsReader.read(text, "r.csv") }.message
        assertEquals("r.csv:1: missing columns icon, response", message("participant,task\nP1,t\n"))
        assertEquals("r.csv:3: response 'NaN' is not a finite decimal number", message("participant,task,icon,response\nP1,t,a,4\nP1,t,b,NaN\n"))
        assertEquals("r.csv:2: response '' is not a finite decimal number", message("participant,task,icon,response\nP1,t,a,\n"))
        // Java's Double.valueOf reads these as 8 and 4: a hex float and a type suffix are not decimal numbers.
        assertEquals("r.csv:2: response '0x1p3' is not a finite decimal number", message("participant,task,icon,response\nP1,t,a,0x1p3\n"))
        assertEquals("r.csv:2: response '4d' is not a finite decimal number", message("participant,task,icon,response\nP1,t,a,4d\n"))
        assertEquals("r.csv:2: expected 4 fields as in the header, found 3", message("participant,task,icon,response\nP1,t,a\n"))
        assertEquals("r.csv:2: empty icon", message("participant,task,icon,response\nP1,t,,4\n"))
        assertEquals("r.csv:1: empty file: expected a header with participant, task, icon, response", message(""))
    }
}
