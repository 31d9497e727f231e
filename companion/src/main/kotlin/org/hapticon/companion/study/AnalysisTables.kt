package org.hapticon.companion.study

import org.hapticon.study.analysis.IconPairComparison
import org.hapticon.study.analysis.IconSummary
import java.math.BigDecimal
import java.math.MathContext

/**
 * The tables `hapticon analyze` writes, as CSV (6 significant digits, empty cell for "undefined" or "not
 * computed") and Markdown (4 significant digits, "–" for those).
 */
object AnalysisTables {
    val DESCRIPTIVES_HEADER: List<String> = listOf("task", "icon", "n", "mean", "sd", "median", "q1", "q3", "iqr", "min", "max")
    val PAIRWISE_HEADER: List<String> =
        listOf("task", "icon_a", "icon_b", "n", "t", "df", "p", "p_holm", "d", "V", "p_wilcoxon", "p_wilcoxon_holm", "dropped")

    /** descriptives.csv. */
    fun descriptivesCsv(summaries: List<IconSummary>): String =
        SpreadsheetCsv.line(DESCRIPTIVES_HEADER) + summaries.joinToString("") { SpreadsheetCsv.line(descriptivesRow(it, CSV_DIGITS)) }

    /** descriptives.md. */
    fun descriptivesMarkdown(summaries: List<IconSummary>): String =
        markdown(DESCRIPTIVES_HEADER, summaries.map { descriptivesRow(it, MARKDOWN_DIGITS) })

    /** pairwise.csv. */
    fun pairwiseCsv(comparisons: List<IconPairComparison>): String =
        SpreadsheetCsv.line(PAIRWISE_HEADER) + comparisons.joinToString("") { SpreadsheetCsv.line(pairwiseRow(it, CSV_DIGITS)) }

    /** pairwise.md. */
    fun pairwiseMarkdown(comparisons: List<IconPairComparison>): String =
        markdown(PAIRWISE_HEADER, comparisons.map { pairwiseRow(it, MARKDOWN_DIGITS) })

    private fun descriptivesRow(s: IconSummary, digits: Int): List<String> {
        val d = s.descriptives
        return listOf(s.task, s.icon, d.n.toString()) +
            listOf(d.mean, d.sd, d.median, d.q1, d.q3, d.iqr, d.min, d.max).map { number(it, digits) }
    }

    private fun pairwiseRow(c: IconPairComparison, digits: Int): List<String> {
        val t = c.tTest
        val w = c.wilcoxon
        return listOf(
            c.task, c.iconA, c.iconB, c.participants.size.toString(),
            number(t?.t, digits), t?.df?.toString().orEmpty(), number(t?.p, digits), number(c.tHolm, digits), number(t?.cohensDz, digits),
            w?.v?.let { rankSum(it) }.orEmpty(), number(w?.p, digits), number(c.wilcoxonHolm, digits),
            c.droppedParticipants.joinToString(";"),
        )
    }

    /** V exactly: a sum of ranks is a whole number or, with ties, ends in .5; rounding it would misreport it. */
    private fun rankSum(v: Double): String = if (v == Math.rint(v)) v.toLong().toString() else v.toString()

    /** [value] to [digits] significant digits, trailing zeros dropped; empty for null. */
    fun number(value: Double?, digits: Int): String {
        if (value == null) return ""
        val rounded = BigDecimal(value).round(MathContext(digits)).stripTrailingZeros()
        if (rounded.signum() == 0) return "0"
        // Plain for ordinary magnitudes; 1.2E-7 style for tiny p-values rather than a run of zeros.
        return if (Math.abs(value) >= 1e-4) rounded.toPlainString() else rounded.toString()
    }

    private fun markdown(header: List<String>, rows: List<List<String>>): String {
        fun cell(text: String) = text.ifEmpty { "–" }.replace("|", "\\|")
        val out = StringBuilder()
        out.append("| ").append(header.joinToString(" | ")).append(" |\n")
        out.append("|").append(header.joinToString("|") { "---" }).append("|\n")
        for (row in rows) out.append("| ").append(row.joinToString(" | ") { cell(it) }).append(" |\n")
        return out.toString()
    }

    private const val CSV_DIGITS = 6
    private const val MARKDOWN_DIGITS = 4
}
