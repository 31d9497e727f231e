package org.hapticon.companion.study

import org.hapticon.study.analysis.IconPairComparison
import org.hapticon.study.analysis.WilcoxonSignedRank
import org.junit.Assert.assertEquals
import org.junit.Test

class AnalysisTablesTest {
    @Test fun numbersKeepSignificantDigitsAndRankSumsStayExact() {
        assertEquals("0.0126766", AnalysisTables.number(0.01267660247801449, 6))
        assertEquals("1.24419E-15", AnalysisTables.number(1.244192114854348e-15, 6))
        assertEquals("0", AnalysisTables.number(0.0, 6))
        assertEquals("20", AnalysisTables.number(20.0, 4))
        assertEquals("", AnalysisTables.number(null, 4))
        val w = WilcoxonSignedRank(n = 500, zeros = 0, ties = true, v = 47252.5, p = 0.20632093217818925, exact = false, undefinedReason = null)
        val c = IconPairComparison("t|x", "a,b", "c", List(500) { "p$it" }, emptyList(), null, w, null, null)
        assertEquals("| t\\|x | a,b | c | 500 | – | – | – | – | – | 47252.5 | 0.2063 | – | – |\n", AnalysisTables.pairwiseMarkdown(listOf(c)).lines()[2] + "\n")
        assertEquals("t|x,\"a,b\",c,500,,,,,,47252.5,0.206321,,\n", AnalysisTables.pairwiseCsv(listOf(c)).lines()[1] + "\n")
    }
}
