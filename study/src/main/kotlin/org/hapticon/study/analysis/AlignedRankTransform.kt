package org.hapticon.study.analysis

import kotlin.math.abs
import kotlin.math.sqrt

/** One observation for [AlignedRankTransform]: [subject]'s [value] under [levels], one level name per factor. */
public data class ArtObservation(val subject: String, val levels: List<String>, val value: Double)

/** One row of an ART ANOVA: [effect] (factor names joined by `:`), F([dfEffect], [dfError]) = [f], p = [p]. */
public data class ArtEffect(val effect: String, val f: Double, val dfEffect: Int, val dfError: Int, val p: Double)

/**
 * One ART-C pairwise contrast of [factor]'s levels [first] − [second]: the difference of their estimated marginal means of
 * the aligned ranks ([estimate], standard error [standardError]), t([df]) = [t], and [p] Tukey-adjusted over the factor's
 * levels (ARTool's `art.con` default).
 */
public data class ArtContrast(
    val factor: String,
    val first: String,
    val second: String,
    val estimate: Double,
    val standardError: Double,
    val df: Int,
    val t: Double,
    val p: Double,
)

/**
 * The aligned rank transform for nonparametric factorial ANOVA with repeated measures (Wobbrock, Findlater, Gergle and
 * Higgins, CHI 2011) as ARTool runs it for `art(y ~ A*B + Error(subject))` followed by `anova()`, and ART-C contrasts
 * (Elkin, Kay, Higgins and Wobbrock, UIST 2021) as `art.con(m, "A")`: Shaping Compliance's analysis
 * (003_8ca1dc8f53472543.txt:161, its references [78] and [12]).
 *
 * For each effect E (main effects in factor order, then two-way interactions, …: R's term order) the response is
 * aligned, y − (full cell mean) + (E's estimated effect, the alternating sum of the cell means of E's factor subsets),
 * rounded to 8 decimals (ARTool's `rank.comparison.digits`) and ranked with ties averaged; a factorial ANOVA with
 * subject as the error stratum then gives E's row only. Every subject must have the same number of observations in
 * every cell (a complete repeated-measures design, as the study's is), so the fixed effects lie in the within-subject
 * stratum and sequential (Type I) sums of squares there are the ones R's `aov` prints. [contrasts] compares a factor's
 * levels on its own aligned ranks with the within-subject residual variance and Tukey's adjustment ([StudentizedRange]).
 *
 * Hand-written (no JVM library has ART); shown equal to a base-R reproduction of the procedure (`aov`, `rank`, `lm`,
 * `vcov`, `pf`, `ptukey`) in the study module's tests.
 *
 * @throws IllegalArgumentException from the constructor for no factors, a level list of the wrong size, a value that is
 *   not finite, fewer than 2 subjects or a cell that some subject has a different number of observations in.
 */
public class AlignedRankTransform(
    /** The factors' names, in the order of [ArtObservation.levels]. */
    public val factors: List<String>,
    observations: List<ArtObservation>,
) {
    private val rows = observations.toList()

    /** Each factor's levels in first-seen order. */
    public val levels: List<List<String>>

    private val subjects: List<String>
    private val subjectOf: IntArray
    private val levelOf: Array<IntArray>
    private val y: DoubleArray

    /** Effects as factor-index lists, in R's term order. */
    private val effects: List<List<Int>>

    init {
        require(factors.isNotEmpty() && factors.toSet().size == factors.size) { "need at least one factor, all named differently" }
        require(factors.none { ':' in it }) { "a factor's name may not contain ':'" }
        require(rows.isNotEmpty()) { "no observations" }
        rows.forEachIndexed { i, o ->
            require(o.levels.size == factors.size) { "observation ${i + 1} has ${o.levels.size} levels for ${factors.size} factors" }
            require(o.value.isFinite()) { "observation ${i + 1} is ${o.value}; values must be finite" }
        }
        levels = factors.indices.map { f -> rows.map { it.levels[f] }.distinct() }
        subjects = rows.map { it.subject }.distinct()
        require(subjects.size >= 2) { "need at least 2 subjects, got ${subjects.size}" }
        val subjectIndex = subjects.withIndex().associate { it.value to it.index }
        subjectOf = IntArray(rows.size) { subjectIndex.getValue(rows[it].subject) }
        levelOf = Array(factors.size) { f -> val index = levels[f].withIndex().associate { it.value to it.index }; IntArray(rows.size) { index.getValue(rows[it].levels[f]) } }
        y = DoubleArray(rows.size) { rows[it].value }
        effects = (1..factors.size).flatMap { size -> subsets(factors.size, size) }
        requireCompleteDesign()
    }

    /** Every effect's ART ANOVA row, in R's term order. */
    public fun anova(): List<ArtEffect> = effects.map { effect ->
        val ranks = alignedRanks(effect)
        val fit = Fit(ranks)
        val index = effects.indexOf(effect)
        val f = (fit.ss[index] / fit.df[index]) / (fit.ssError / fit.dfError)
        ArtEffect(effect.joinToString(":") { factors[it] }, f, fit.df[index], fit.dfError, fUpperTail(f, fit.df[index].toDouble(), fit.dfError.toDouble()))
    }

    /**
     * The ART-C pairwise contrasts of [factor]'s levels (every pair, in level order), on the ranks aligned for its main
     * effect: ARTool's `art.con(m, factor)` with its default Tukey adjustment.
     * @throws IllegalArgumentException for a factor that is not one of [factors] or has a single level.
     */
    public fun contrasts(factor: String): List<ArtContrast> {
        val f = factors.indexOf(factor)
        require(f >= 0) { "no factor '$factor' (factors: ${factors.joinToString()})" }
        val count = levels[f].size
        require(count >= 2) { "'$factor' has one level: nothing to compare" }
        val ranks = alignedRanks(listOf(f))
        val fit = Fit(ranks)
        val sigma2 = fit.ssError / fit.dfError
        // Estimated marginal means: each level's cell means of the ranks, averaged with equal weight over the other factors' cells.
        val cellSum = HashMap<List<Int>, Double>()
        val cellCount = HashMap<List<Int>, Int>()
        for (i in rows.indices) {
            val cell = cellOf(i)
            cellSum.merge(cell, ranks[i], Double::plus)
            cellCount.merge(cell, 1, Int::plus)
        }
        val emm = DoubleArray(count)
        val variance = DoubleArray(count)
        for (level in 0 until count) {
            val cells = cellSum.keys.filter { it[f] == level }
            for (cell in cells) {
                emm[level] += cellSum.getValue(cell) / cellCount.getValue(cell) / cells.size
                variance[level] += 1.0 / (cellCount.getValue(cell).toDouble() * cells.size * cells.size)
            }
        }
        val out = ArrayList<ArtContrast>()
        for (a in 0 until count) for (b in a + 1 until count) {
            val estimate = emm[a] - emm[b]
            val se = sqrt(sigma2 * (variance[a] + variance[b]))
            val t = estimate / se
            out += ArtContrast(factor, levels[f][a], levels[f][b], estimate, se, fit.dfError, t, StudentizedRange.upperTail(abs(t) * sqrt(2.0), count, fit.dfError.toDouble()))
        }
        return out
    }

    /** The ranks (ties averaged) of the responses aligned for [effect]. */
    internal fun alignedRanks(effect: List<Int>): DoubleArray {
        val full = cellMeans(factors.indices.toList())
        val aligned = DoubleArray(rows.size) { i -> y[i] - full[i] }
        for (subset in (0..effect.size).flatMap { subsets(effect.size, it) }) {
            val sign = if ((effect.size - subset.size) % 2 == 0) 1.0 else -1.0
            val means = cellMeans(subset.map { effect[it] })
            for (i in rows.indices) aligned[i] += sign * means[i]
        }
        return averageRanks(List(rows.size) { Math.rint(aligned[it] * RANK_SCALE) / RANK_SCALE })
    }

    /** Each row's mean of y over the rows sharing its levels of [factorSet] (the grand mean for none). */
    private fun cellMeans(factorSet: List<Int>): DoubleArray {
        val sum = HashMap<List<Int>, Double>()
        val n = HashMap<List<Int>, Int>()
        val keys = rows.indices.map { i -> factorSet.map { levelOf[it][i] } }
        for (i in rows.indices) {
            sum.merge(keys[i], y[i], Double::plus)
            n.merge(keys[i], 1, Int::plus)
        }
        return DoubleArray(rows.size) { sum.getValue(keys[it]) / n.getValue(keys[it]) }
    }

    private fun cellOf(row: Int): List<Int> = factors.indices.map { levelOf[it][row] }

    private fun requireCompleteDesign() {
        val cells = levels.fold(listOf(emptyList<Int>())) { acc, l -> acc.flatMap { prefix -> l.indices.map { prefix + it } } }
        val counts = HashMap<Pair<Int, List<Int>>, Int>()
        for (i in rows.indices) counts.merge(subjectOf[i] to cellOf(i), 1, Int::plus)
        for (cell in cells) {
            val perSubject = subjects.indices.map { counts[it to cell] ?: 0 }
            val name = cell.withIndex().joinToString(", ") { "${factors[it.index]} ${levels[it.index][it.value]}" }
            require(perSubject.all { it > 0 }) { "$name: ${subjects[perSubject.indexOfFirst { it == 0 }]} has no observation there (the design must be complete)" }
            require(perSubject.distinct().size == 1) {
                val odd = perSubject.indexOfFirst { it != perSubject[0] }
                "$name: ${subjects[0]} has ${perSubject[0]} observations, ${subjects[odd]} ${perSubject[odd]} (every subject needs the same number in every cell)"
            }
        }
    }

    /**
     * The within-subject stratum's sequential sums of squares of [response] for every effect, in order, and the
     * residual's: the response centred on each subject's mean, the effects' sum-to-zero coded columns centred (each
     * subject has the same cells, so a column's subject means are its grand mean), orthogonalised in order.
     */
    private inner class Fit(response: DoubleArray) {
        val ss = DoubleArray(effects.size)
        val df = IntArray(effects.size)
        val ssError: Double
        val dfError: Int

        init {
            val subjectMean = DoubleArray(subjects.size)
            val subjectCount = IntArray(subjects.size)
            for (i in rows.indices) {
                subjectMean[subjectOf[i]] += response[i]
                subjectCount[subjectOf[i]]++
            }
            for (s in subjects.indices) subjectMean[s] /= subjectCount[s]
            val r = DoubleArray(rows.size) { response[it] - subjectMean[subjectOf[it]] }
            val total = r.sumOf { it * it }
            val basis = ArrayList<DoubleArray>()
            for ((e, effect) in effects.withIndex()) {
                for (column in columns(effect)) {
                    val mean = column.average()
                    val v = DoubleArray(column.size) { column[it] - mean }
                    val norm = sqrt(v.sumOf { it * it })
                    // Twice through Gram–Schmidt: one pass loses orthogonality on near-collinear columns.
                    repeat(2) { for (q in basis) { val dot = dot(q, v); for (i in v.indices) v[i] -= dot * q[i] } }
                    val left = sqrt(v.sumOf { it * it })
                    if (left <= ALIASED * norm) continue
                    for (i in v.indices) v[i] /= left
                    basis += v
                    val projection = dot(v, r)
                    ss[e] += projection * projection
                    df[e]++
                }
            }
            ssError = (total - ss.sum()).coerceAtLeast(0.0)
            dfError = rows.size - subjects.size - df.sum()
            require(dfError > 0) { "no residual degrees of freedom: every subject needs more than one observation per cell, or more cells" }
        }

        /** [effect]'s columns: products of each of its factors' sum-to-zero codes (level j < L−1: e_j; the last: all −1). */
        private fun columns(effect: List<Int>): List<DoubleArray> =
            effect.fold(listOf(DoubleArray(rows.size) { 1.0 })) { acc, f ->
                val codes = (0 until levels[f].size - 1).map { j ->
                    DoubleArray(rows.size) { i -> when (levelOf[f][i]) { j -> 1.0; levels[f].size - 1 -> -1.0; else -> 0.0 } }
                }
                acc.flatMap { a -> codes.map { c -> DoubleArray(rows.size) { a[it] * c[it] } } }
            }
    }

    private companion object {
        /** ARTool rounds aligned responses to −⌊log10 √ε⌋ = 8 digits before ranking, so equal values tie. */
        const val RANK_SCALE = 1e8

        /** A column left with less than this share of its length after orthogonalising is aliased (no new df). */
        const val ALIASED = 1e-9

        fun dot(a: DoubleArray, b: DoubleArray): Double {
            var s = 0.0
            for (i in a.indices) s += a[i] * b[i]
            return s
        }

        /** The [size]-element subsets of 0 until [n], in lexicographic order. */
        fun subsets(n: Int, size: Int, from: Int = 0): List<List<Int>> =
            if (size == 0) listOf(emptyList()) else (from until n).flatMap { first -> subsets(n, size - 1, first + 1).map { listOf(first) + it } }

        /** P(F > [f]) for an F([df1], [df2]) variable: I_{df2/(df2 + df1·f)}(df2/2, df1/2). */
        fun fUpperTail(f: Double, df1: Double, df2: Double): Double {
            if (f.isNaN()) return Double.NaN
            if (f <= 0.0) return 1.0
            if (f.isInfinite()) return 0.0
            val denominator = df2 + df1 * f
            return SpecialFunctions.incompleteBeta(df2 / 2, df1 / 2, df2 / denominator, df1 * f / denominator)
        }
    }
}
