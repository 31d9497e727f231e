package org.hapticon.companion.study

import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import java.nio.file.Files

class AnalysisBenchTest {
    @Test fun writeResults_thousandRows_writesEveryParticipantTaskIconAndTrialButTheSkippedOnes() {
        val file = Files.createTempFile("results", ".csv").toFile()
        try {
            val participants = AnalysisBench.writeResults(file, 1_000)
            assertEquals(8, participants)
            val responses = ResultsReader.read(file.readText(), file.name)
            assertEquals(8 * 4 * 6 * 5, responses.size) // no participant number is a multiple of 97
            assertEquals(setOf(1.0, 2.0, 3.0, 4.0, 5.0), responses.map { it.response }.toSet())
        } finally {
            file.delete()
        }
    }

    @Test fun run_quick_measuresEverySizeAndPrintsGrowth() {
        val steps = ArrayList<String>()
        val sizes = AnalysisBench(AnalysisBench.Config.QUICK) { steps += it }.run()
        assertEquals(listOf(1_000, 10_000), sizes.map { it.rows })
        assertEquals(listOf(8, 83), sizes.map { it.participants })
        assertTrue(sizes.all { it.seconds.size == 2 && it.seconds.all { s -> s > 0.0 } && it.peakHeapBytes > 0 })
        assertEquals(3, steps.size)
        val table = AnalysisBench.table(sizes)
        assertTrue(table, Regex("""\n\s+10000\s+83 .* \d+\.\d\dx """).containsMatchIn(table))
    }

    @Test fun run_quick_timesBothCsvReadersOnEverySize() {
        val sizes = AnalysisBench(AnalysisBench.Config.QUICK).run()
        assertTrue(sizes.all { it.read.ours.size == 2 && it.read.commonsCsv.size == 2 && (it.read.ours + it.read.commonsCsv).all { s -> s > 0.0 } })
        val table = AnalysisBench.table(sizes)
        assertTrue(table, Regex("""our reader +commons-csv +ratio\n +1000 +\d+\.\d +\d+\.\d +\d+\.\d\dx\n +10000 """).containsMatchIn(table))
    }
}
