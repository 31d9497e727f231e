package org.hapticon.study.analysis

import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertThrows
import org.junit.Test

class StudyAnalysisTest {
    private fun r(participant: String, task: String, icon: String, response: Double) = StudyResponse(participant, task, icon, response)

    private val rows = listOf(
        r("p1", "calm", "stroke", 4.0), r("p1", "calm", "knock", 2.0), r("p1", "calm", "hug", 5.0),
        r("p2", "calm", "stroke", 5.0), r("p2", "calm", "knock", 1.0), r("p2", "calm", "hug", 4.0),
        r("p3", "calm", "stroke", 3.0), r("p3", "calm", "knock", 2.0),
        r("p1", "urgent", "knock", 5.0), r("p1", "urgent", "knock", 3.0), r("p1", "urgent", "hit", 2.0),
        r("p2", "urgent", "knock", 4.0), r("p2", "urgent", "hit", 1.0),
    )

    @Test fun describesEachTaskAndIconInOrder() {
        val summaries = StudyAnalysis.describe(rows)
        assertEquals(listOf("calm/stroke", "calm/knock", "calm/hug", "urgent/knock", "urgent/hit"), summaries.map { "${it.task}/${it.icon}" })
        assertEquals(3, summaries[0].descriptives.n)
        assertEquals(4.0, summaries[0].descriptives.mean, 0.0)
        assertEquals(3, summaries[3].descriptives.n) // every response counts in the descriptives
    }

    @Test fun comparesPairsWithinTasksDroppingUnpaired() {
        val comparisons = StudyAnalysis.compare(rows, holm = true)
        assertEquals(listOf("calm stroke-knock", "calm stroke-hug", "calm knock-hug", "urgent knock-hit"),
            comparisons.map { "${it.task} ${it.iconA}-${it.iconB}" })
        val strokeHug = comparisons[1]
        assertEquals(listOf("p1", "p2"), strokeHug.participants)
        assertEquals(listOf("p3"), strokeHug.droppedParticipants)
        // stroke − hug = −1, +1: mean 0, SD √2, t = 0, p = 1.
        assertEquals(0.0, strokeHug.tTest!!.t!!, 0.0)
        assertEquals(1.0, strokeHug.tTest!!.p!!, 1e-15)
        // p1 rated knock twice in "urgent": their mean 4 pairs with hit 2; p2: 4 − 1; differences 2, 3.
        val urgent = comparisons[3]
        assertEquals(2.5, urgent.tTest!!.meanDifference!!, 0.0)
        // The only pair of its task: Holm leaves p as it is.
        assertEquals(urgent.tTest!!.p!!, urgent.tHolm!!, 0.0)
        // stroke − knock = 2, 4, 1 → t = 7/3 / (SD 1.5275 / √3) = 2.6457513, df 2.
        assertEquals(2.6457513110645907, comparisons[0].tTest!!.t!!, 1e-12)
    }

    @Test fun holmAcrossTaskPairsSkipsUndefinedTests() {
        val constant = listOf(
            r("a", "t", "x", 3.0), r("a", "t", "y", 2.0), r("a", "t", "z", 5.0),
            r("b", "t", "x", 4.0), r("b", "t", "y", 3.0), r("b", "t", "z", 1.0),
        )
        val comparisons = StudyAnalysis.compare(constant, holm = true)
        // x − y = 1, 1: undefined, so Holm spreads over the two other pairs only.
        assertNull(comparisons[0].tTest!!.p)
        assertNull(comparisons[0].tHolm)
        val p = comparisons.drop(1).map { it.tTest!!.p!! }
        assertEquals(Holm.adjust(p), comparisons.drop(1).map { it.tHolm!! })
    }

    @Test fun testsNotAskedForAreNull() {
        val onlyWilcoxon = StudyAnalysis.compare(rows, tTest = false)
        assertNull(onlyWilcoxon[0].tTest)
        assertNull(onlyWilcoxon[0].tHolm)
        assertEquals(6.0, onlyWilcoxon[0].wilcoxon!!.v, 0.0)
    }

    @Test fun nanResponseIsRejectedWithAMessage() {
        val e = assertThrows(IllegalArgumentException::class.java) { r("p9", "calm", "hug", Double.NaN) }
        assertEquals("response of participant 'p9' to icon 'hug' in task 'calm' is NaN, not a number", e.message)
    }

    @Test fun emptyInputGivesNoRows() {
        assertEquals(emptyList<IconSummary>(), StudyAnalysis.describe(emptyList()))
        assertEquals(emptyList<IconPairComparison>(), StudyAnalysis.compare(emptyList()))
    }
}
