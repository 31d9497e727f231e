package org.hapticon.study.analysis

/**
 * One rating from the long-format results: [participant] gave [response] (a Likert value, say) to [icon]
 * in [task]. Only the columns the analysis needs; [response] must be finite.
 */
public data class StudyResponse(
    val participant: String,
    val task: String,
    val icon: String,
    val response: Double,
) {
    init {
        require(response.isFinite()) { "response of participant '$participant' to icon '$icon' in task '$task' is $response, not a number" }
    }
}

/** [descriptives] of every response to [icon] in [task]. */
public data class IconSummary(val task: String, val icon: String, val descriptives: Descriptives)

/**
 * The paired comparison of [iconA] with [iconB] in [task] (differences A − B) over the [participants] who
 * rated both; [droppedParticipants] rated only one of them. [tTest] and [wilcoxon] are null when not
 * asked for; [tHolm] and [wilcoxonHolm] are their Holm-adjusted p over the pairs of the task, null when
 * not asked for or the test is undefined.
 */
public data class IconPairComparison(
    val task: String,
    val iconA: String,
    val iconB: String,
    val participants: List<String>,
    val droppedParticipants: List<String>,
    val tTest: PairedTTest?,
    val wilcoxon: WilcoxonSignedRank?,
    val tHolm: Double?,
    val wilcoxonHolm: Double?,
)

/** The study's analysis: descriptives per (task, icon) and paired tests for every icon pair in a task. */
public object StudyAnalysis {
    /** Descriptives of all responses per (task, icon), tasks and icons in order of first appearance. */
    public fun describe(responses: List<StudyResponse>): List<IconSummary> =
        responses.groupBy { it.task }.flatMap { (task, rows) ->
            rows.groupBy { it.icon }.map { (icon, iconRows) -> IconSummary(task, icon, Descriptives.of(iconRows.map { it.response })) }
        }

    /**
     * Every pair of icons within each task (in order of first appearance), compared with the paired t-test
     * when [tTest] and the Wilcoxon signed-rank test when [wilcoxon]; with [holm] their p-values are also
     * Holm-adjusted across the pairs of the task. A participant who rated an icon more than once (several
     * trials) counts with the mean of those ratings, so each participant is one pair.
     */
    public fun compare(responses: List<StudyResponse>, tTest: Boolean = true, wilcoxon: Boolean = true, holm: Boolean = false): List<IconPairComparison> =
        responses.groupBy { it.task }.flatMap { (task, rows) -> compareTask(task, rows, tTest, wilcoxon, holm) }

    private fun compareTask(task: String, rows: List<StudyResponse>, tTest: Boolean, wilcoxon: Boolean, holm: Boolean): List<IconPairComparison> {
        // icon -> participant -> mean rating, both in order of first appearance.
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
            comparisons += IconPairComparison(
                task, icons[i], icons[j], both, dropped,
                if (tTest) PairedTTest.of(first, second) else null,
                if (wilcoxon) WilcoxonSignedRank.of(first, second) else null,
                null, null,
            )
        }
        if (!holm) return comparisons
        val tAdjusted = adjustDefined(comparisons.map { it.tTest?.p })
        val wAdjusted = adjustDefined(comparisons.map { it.wilcoxon?.p })
        return comparisons.mapIndexed { k, c -> c.copy(tHolm = tAdjusted[k], wilcoxonHolm = wAdjusted[k]) }
    }

    /** Holm over the non-null p-values only (an undefined test is not a comparison made); nulls stay null. */
    private fun adjustDefined(pValues: List<Double?>): List<Double?> {
        val defined = pValues.withIndex().filter { it.value != null }
        val adjusted = Holm.adjust(defined.map { it.value!! })
        val result = arrayOfNulls<Double>(pValues.size)
        defined.forEachIndexed { k, indexed -> result[indexed.index] = adjusted[k] }
        return result.toList()
    }
}
