package org.hapticon.companion.plot

import java.awt.Graphics2D
import java.awt.geom.Line2D

/**
 * A polyline through any number of samples, reduced to what pixel columns can show: per column the first
 * and last sample (with their exact horizontal positions) and the smallest and largest value. Joining the
 * first and last samples of consecutive columns, plus a vertical min–max stroke where a column holds
 * extremes beyond its first and last, draws the same picture as the full polyline: a smooth line for an
 * envelope, a min/max band for a dense carrier. Memory is six numbers per column however long the signal is.
 */
class ColumnExtremes(
    /** Number of columns. */
    val columns: Int,
) {
    private val firstX = DoubleArray(columns)
    private val first = DoubleArray(columns)
    private val lastX = DoubleArray(columns)
    private val last = DoubleArray(columns)
    private val min = DoubleArray(columns) { Double.POSITIVE_INFINITY }
    private val max = DoubleArray(columns) { Double.NEGATIVE_INFINITY }
    private val filled = BooleanArray(columns)

    /**
     * Adds [value], the next sample in time order, at horizontal offset [x] pixels from the area's left
     * edge; its column is floor(x), clamped to the columns there are.
     */
    fun add(x: Double, value: Double) {
        val column = x.toInt().coerceIn(0, columns - 1)
        if (!filled[column]) {
            filled[column] = true
            firstX[column] = x
            first[column] = value
        }
        lastX[column] = x
        last[column] = value
        if (value < min[column]) min[column] = value
        if (value > max[column]) max[column] = value
    }

    /** True when some sample fell in [column]. */
    fun hasValues(column: Int): Boolean = filled[column]

    /** Smallest value in [column]; only meaningful when [hasValues]. */
    fun minAt(column: Int): Double = min[column]

    /** Largest value in [column]; only meaningful when [hasValues]. */
    fun maxAt(column: Int): Double = max[column]

    /** Draws the polyline with [g]'s current colour and stroke, values mapped by [area] after multiplying by [scale] (−1 mirrors). */
    fun draw(g: Graphics2D, area: PlotArea, scale: Double = 1.0) {
        val line = Line2D.Double()
        fun segment(x1: Double, v1: Double, x2: Double, v2: Double) {
            line.setLine(area.left + x1, area.y(scale * v1), area.left + x2, area.y(scale * v2))
            g.draw(line)
        }
        var previous = -1
        for (c in 0 until columns) {
            if (!filled[c]) continue
            if (previous >= 0) segment(lastX[previous], last[previous], firstX[c], first[c])
            segment(firstX[c], first[c], lastX[c], last[c])
            if (min[c] < minOf(first[c], last[c]) || max[c] > maxOf(first[c], last[c])) {
                val x = c + 0.5
                segment(x, min[c], x, max[c])
            }
            previous = c
        }
    }
}
