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

/**
 * The study's analysis: descriptives per (task, icon) and paired tests for every icon pair in a task.
 *
 * Cost is linear in the rows: names become small integer ids once ([ResponseColumns]), responses are
 * gathered per (task, icon) cell into primitive arrays, and each pair's participants are matched through
 * a dense id-indexed table rather than by searching lists (which would make a million rows take 15× as long as
 * 100k). Sums run in row order, so every figure is the same to the bit whatever the table's layout.
 */
public object StudyAnalysis {
    /** Descriptives of all responses per (task, icon), tasks and icons in order of first appearance. */
    public fun describe(responses: List<StudyResponse>): List<IconSummary> {
        val columns = ResponseColumns(responses)
        return columns.cellsByTask().flatMap { cells ->
            cells.map { cell -> IconSummary(columns.taskOf(cell), columns.iconOf(cell), Descriptives.of(columns.valuesOf(cell))) }
        }
    }

    /**
     * Every pair of icons within each task (in order of first appearance), compared with the paired t-test
     * when [tTest] and the Wilcoxon signed-rank test when [wilcoxon]; with [holm] their p-values are also
     * Holm-adjusted across the pairs of the task. A participant who rated an icon more than once (several
     * trials) counts with the mean of those ratings, so each participant is one pair.
     */
    public fun compare(responses: List<StudyResponse>, tTest: Boolean = true, wilcoxon: Boolean = true, holm: Boolean = false): List<IconPairComparison> {
        val columns = ResponseColumns(responses)
        val means = columns.participantMeans()
        // slot[p] = index of participant p in the second icon's means, -1 when absent; reset after each pair.
        val slot = IntArray(columns.participantCount) { -1 }
        return columns.cellsByTask().flatMap { cells ->
            val comparisons = ArrayList<IconPairComparison>()
            for (i in cells.indices) for (j in i + 1 until cells.size) {
                comparisons += comparePair(columns, means[cells[i]], means[cells[j]], slot, tTest, wilcoxon)
            }
            if (holm) withHolm(comparisons) else comparisons
        }
    }

    private fun comparePair(columns: ResponseColumns, a: CellMeans, b: CellMeans, slot: IntArray, tTest: Boolean, wilcoxon: Boolean): IconPairComparison {
        for (k in b.participants.indices) slot[b.participants[k]] = k
        val both = ArrayList<String>()
        val first = ArrayList<Double>()
        val second = ArrayList<Double>()
        val dropped = ArrayList<String>()
        val inA = BooleanArray(b.participants.size)
        for (k in a.participants.indices) {
            val p = a.participants[k]
            val other = slot[p]
            if (other < 0) {
                dropped += columns.participantName(p)
            } else {
                inA[other] = true
                both += columns.participantName(p)
                first += a.means[k]
                second += b.means[other]
            }
        }
        for (k in b.participants.indices) {
            if (!inA[k]) dropped += columns.participantName(b.participants[k])
            slot[b.participants[k]] = -1
        }
        return IconPairComparison(
            columns.taskOf(a.cell), columns.iconOf(a.cell), columns.iconOf(b.cell), both, dropped,
            if (tTest) PairedTTest.of(first, second) else null,
            if (wilcoxon) WilcoxonSignedRank.of(first, second) else null,
            null, null,
        )
    }

    private fun withHolm(comparisons: List<IconPairComparison>): List<IconPairComparison> {
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

/** One cell's participants (ids, in order of first appearance in the cell) and their mean responses. */
internal class CellMeans(val cell: Int, val participants: IntArray, val means: DoubleArray)

/**
 * [responses] as columns of ids: each row's participant id and (task, icon) cell id, numbered in order of
 * first appearance, and its response. Everything downstream is arrays indexed by these ids.
 */
internal class ResponseColumns(responses: List<StudyResponse>) {
    private val participantNames = ArrayList<String>()
    private val cellTasks = ArrayList<String>()
    private val cellIcons = ArrayList<String>()
    private val rowParticipant = IntArray(responses.size)
    private val rowCell = IntArray(responses.size)
    private val rowValue = DoubleArray(responses.size)

    /** Cell ids per task, tasks in order of first appearance, cells in order of first appearance within the task. */
    private val tasks = LinkedHashMap<String, MutableList<Int>>()

    init {
        val participantIds = HashMap<String, Int>()
        val cellIds = HashMap<String, HashMap<String, Int>>()
        for ((row, r) in responses.withIndex()) {
            rowParticipant[row] = participantIds.getOrPut(r.participant) { participantNames.add(r.participant); participantNames.size - 1 }
            rowCell[row] = cellIds.getOrPut(r.task) { HashMap() }.getOrPut(r.icon) {
                cellTasks.add(r.task)
                cellIcons.add(r.icon)
                tasks.getOrPut(r.task) { ArrayList() }.add(cellTasks.size - 1)
                cellTasks.size - 1
            }
            rowValue[row] = r.response
        }
    }

    val participantCount: Int get() = participantNames.size

    fun participantName(id: Int): String = participantNames[id]

    fun taskOf(cell: Int): String = cellTasks[cell]

    fun iconOf(cell: Int): String = cellIcons[cell]

    fun cellsByTask(): Collection<List<Int>> = tasks.values

    /** Row indices grouped by cell (a counting sort, rows in order within each cell) and each cell's start. */
    private val grouped: Pair<IntArray, IntArray> by lazy {
        val start = IntArray(cellTasks.size + 1)
        for (c in rowCell) start[c + 1]++
        for (c in 0 until cellTasks.size) start[c + 1] += start[c]
        val next = start.copyOf()
        val rows = IntArray(rowCell.size)
        for (row in rowCell.indices) rows[next[rowCell[row]]++] = row
        rows to start
    }

    /** The responses of [cell] in row order. */
    fun valuesOf(cell: Int): DoubleArray {
        val (rows, start) = grouped
        return DoubleArray(start[cell + 1] - start[cell]) { rowValue[rows[start[cell] + it]] }
    }

    /** Every cell's per-participant means: sums in row order over the participant's count, as `average()` does. */
    fun participantMeans(): List<CellMeans> {
        val (rows, start) = grouped
        val slot = IntArray(participantCount) { -1 }
        return List(cellTasks.size) { cell ->
            val ids = IntArray(start[cell + 1] - start[cell])
            val sums = DoubleArray(ids.size)
            val counts = IntArray(ids.size)
            var distinct = 0
            for (k in start[cell] until start[cell + 1]) {
                val p = rowParticipant[rows[k]]
                var s = slot[p]
                if (s < 0) {
                    s = distinct++
                    slot[p] = s
                    ids[s] = p
                }
                sums[s] += rowValue[rows[k]]
                counts[s]++
            }
            for (s in 0 until distinct) slot[ids[s]] = -1
            CellMeans(cell, ids.copyOf(distinct), DoubleArray(distinct) { sums[it] / counts[it] })
        }
    }
}
