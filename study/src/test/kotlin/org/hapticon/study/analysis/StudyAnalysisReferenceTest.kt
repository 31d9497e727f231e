package org.hapticon.study.analysis

import org.junit.Assert.assertEquals
import org.junit.Test
import java.util.SplittableRandom

/**
 * The columnar [StudyAnalysis] against the straightforward grouping it replaced (kept here as the
 * reference): on ragged data with repeated trials, missing ratings and ties, every figure is bit-identical.
 */
class StudyAnalysisReferenceTest {
    private fun referenceDescribe(responses: List<StudyResponse>): List<IconSummary> =
        responses.groupBy { it.task }.flatMap { (task, rows) ->
            rows.groupBy { it.icon }.map { (icon, iconRows) -> IconSummary(task, icon, referenceDescriptives(iconRows.map { it.response })) }
        }

    private fun referenceDescriptives(values: List<Double>): Descriptives {
        val sorted = values.sorted()
        val mean = values.average()
        var squares = 0.0
        for (v in values) squares += (v - mean) * (v - mean)
        val sd = if (values.size < 2) null else kotlin.math.sqrt(squares / (values.size - 1))
        return Descriptives(values.size, mean, sd, Descriptives.quantile(sorted, 0.5), Descriptives.quantile(sorted, 0.25), Descriptives.quantile(sorted, 0.75), sorted.first(), sorted.last())
    }

    private fun referenceCompare(responses: List<StudyResponse>): List<IconPairComparison> =
        responses.groupBy { it.task }.flatMap { (task, rows) ->
            val means = rows.groupBy { it.icon }.mapValues { (_, iconRows) ->
                iconRows.groupBy { it.participant }.mapValues { (_, own) -> own.map { it.response }.average() }
            }
            val icons = means.keys.toList()
            val comparisons = ArrayList<IconPairComparison>()
            for (i in icons.indices) for (j in i + 1 until icons.size) {
                val a = means.getValue(icons[i])
                val b = means.getValue(icons[j])
                val both = a.keys.filter { it in b }
                val dropped = (a.keys + b.keys).filter { it !in both }.distinct()
                val first = both.map { a.getValue(it) }
                val second = both.map { b.getValue(it) }
                comparisons += IconPairComparison(task, icons[i], icons[j], both, dropped, PairedTTest.of(first, second), WilcoxonSignedRank.of(first, second), null, null)
            }
            comparisons
        }

    private fun raggedStudy(seed: Long, rows: Int): List<StudyResponse> {
        val random = SplittableRandom(seed)
        return List(rows) {
            StudyResponse(
                "p" + random.nextInt(40),
                "task" + random.nextInt(3),
                "icon" + random.nextInt(5),
                // Likert steps (ties) and a few fractional, negative and zero values.
                if (random.nextInt(10) == 0) random.nextDouble(-2.0, 7.0) else (1 + random.nextInt(5)).toDouble(),
            )
        }
    }

    @Test fun describe_raggedStudy_isBitIdenticalToTheGroupingReference() {
        for (seed in 1L..5L) {
            val responses = raggedStudy(seed, 600)
            assertEquals(referenceDescribe(responses), StudyAnalysis.describe(responses))
        }
    }

    @Test fun compare_raggedStudyWithMissingRatings_isBitIdenticalToTheGroupingReference() {
        for (seed in 1L..5L) {
            val responses = raggedStudy(seed, 600)
            val expected = referenceCompare(responses)
            assertEquals(expected, StudyAnalysis.compare(responses))
            assert(expected.any { it.droppedParticipants.isNotEmpty() }) { "the data must exercise dropped participants" }
        }
    }

    @Test fun describe_doubleArrayAndList_agree() {
        val values = doubleArrayOf(3.0, -0.0, 0.0, 5.5, 1.0, 1.0)
        assertEquals(Descriptives.of(values.toList()), Descriptives.of(values))
        assertEquals(doubleArrayOf(3.0, -0.0, 0.0, 5.5, 1.0, 1.0).toList(), values.toList()) // not sorted in place
    }
}
