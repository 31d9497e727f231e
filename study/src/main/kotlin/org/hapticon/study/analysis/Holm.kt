package org.hapticon.study.analysis

/** The Holm–Bonferroni step-down correction for multiple comparisons. */
public object Holm {
    /**
     * Holm-adjusted p-values of [pValues], in the same order: sorted ascending, the i-th smallest of m is
     * multiplied by m − i + 1, made non-decreasing and capped at 1 (R's `p.adjust(p, "holm")`).
     * Throws [IllegalArgumentException] when a value is not in [0, 1].
     */
    public fun adjust(pValues: List<Double>): List<Double> {
        pValues.forEachIndexed { i, p -> require(p in 0.0..1.0) { "p-value ${i + 1} must be in [0, 1], got $p" } }
        val m = pValues.size
        val order = pValues.indices.sortedBy { pValues[it] }
        val adjusted = DoubleArray(m)
        var running = 0.0
        for ((rank, index) in order.withIndex()) {
            running = maxOf(running, minOf(1.0, (m - rank) * pValues[index]))
            adjusted[index] = running
        }
        return adjusted.toList()
    }
}
