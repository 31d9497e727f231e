package org.hapticon.study.compliance

import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.electrotactile.ElectrodePattern
import java.util.Locale
import kotlin.math.roundToInt

/** A point of a drawn contour on the drawing area: [x] rightwards and [y] downwards, each 0..1 of the area's side. */
public data class DrawingPoint(val x: Double, val y: Double) {
    init {
        require(x in 0.0..1.0 && y in 0.0..1.0) { "a drawing point must lie in 0..1, was ($x, $y)" }
    }
}

/**
 * One Task 2 answer (003_8ca1dc8f53472543.txt:175): [participant] felt [condition] in repetition [repetition], said
 * whether it was [moreCompliant] than the bare desk, and drew [contours], each a closed outline (the last point joins
 * the first) of an area where compliance was felt; several separate contours are allowed.
 */
public data class ShapeDrawing(
    val participant: String,
    val repetition: Int,
    val condition: ComplianceCondition,
    val moreCompliant: Boolean,
    val contours: List<List<DrawingPoint>>,
)

/** Figure 5's heatmap of one shape: [levels] (0..255, row by row, [ShapeDrawings.SIZE] square) over [drawings] drawings. */
public class ShapeHeatmap(public val shape: ElectrodeMask, public val drawings: Int, private val levels: IntArray) {
    /** The level at pixel ([x], [y]), 0..255. */
    public fun level(x: Int, y: Int): Int = levels[y * ShapeDrawings.SIZE + x]

    /** Whether pixel ([x], [y]) is shown in Figure 5: at or above the threshold, level 128 of 256 (:159). */
    public fun shown(x: Int, y: Int): Boolean = level(x, y) >= ShapeDrawings.THRESHOLD

    /**
     * The 3×3 cells (the electrodes' places: the square cut in thirds) where most pixels are shown, as a pattern; null
     * when none is. A summary of the heatmap beside the shape's active electrodes (the figure's own comparison, :179).
     */
    public fun feltCells(): ElectrodePattern? {
        val third = ShapeDrawings.SIZE / 3.0
        var bits = 0
        for (cell in 0 until 9) {
            val x0 = ((cell % 3) * third).roundToInt()
            val y0 = ((cell / 3) * third).roundToInt()
            val x1 = ((cell % 3 + 1) * third).roundToInt()
            val y1 = ((cell / 3 + 1) * third).roundToInt()
            var shown = 0
            for (y in y0 until y1) for (x in x0 until x1) if (shown(x, y)) shown++
            if (shown * 2 > (x1 - x0) * (y1 - y0)) bits = bits or (1 shl cell)
        }
        return if (bits == 0) null else ElectrodePattern(bits)
    }
}

/**
 * Task 2's drawings: stored with each trial as text ([encode], [decode]) and aggregated as the paper's Figure 5
 * ([heatmaps], :177): each participant's contours scaled from the bounding box of all their contours to a 340 × 340
 * square, filled and overlaid per shape, the counts scaled to 256 levels with the brightest pixel of all heatmaps as
 * 255, and shown from level 128. Trials felt less compliant than the desk are left out, as the paper removed its one
 * (:175). Whether a trial's separate contours add up or count once where they overlap is paper silent: ours counts a
 * pixel once per trial (the area felt), and the bounding box scales x and y each to the square (the paper's "a
 * transformation matrix from this bounding box to a square").
 */
public object ShapeDrawings {
    /** The heatmaps' side in pixels: 340 (:177). */
    public const val SIZE: Int = 340

    /** The level from which a pixel is shown: 128 of 256 (:159, :177). */
    public const val THRESHOLD: Int = 128

    /**
     * [contours] as one line of text for a CSV cell: points `x:y` (4 decimals) separated by spaces, contours by `|`; no
     * comma or quote, so the cell needs no quoting. Empty for no contour.
     */
    public fun encode(contours: List<List<DrawingPoint>>): String =
        contours.joinToString("|") { contour -> contour.joinToString(" ") { String.format(Locale.ROOT, "%.4f:%.4f", it.x, it.y) } }

    /**
     * The contours in [text] as [encode] writes them.
     * @throws IllegalArgumentException naming the first malformed point.
     */
    public fun decode(text: String): List<List<DrawingPoint>> {
        if (text.isBlank()) return emptyList()
        return text.split('|').map { contour ->
            contour.trim().split(' ').filter { it.isNotEmpty() }.map { point ->
                val parts = point.split(':')
                val x = parts.getOrNull(0)?.toDoubleOrNull()
                val y = parts.getOrNull(1)?.toDoubleOrNull()
                require(parts.size == 2 && x != null && y != null) { "not a drawing point: '$point' (expected x:y)" }
                DrawingPoint(x, y)
            }
        }
    }

    /** Figure 5's heatmap for each shape drawn, in first-seen order. */
    public fun heatmaps(drawings: List<ShapeDrawing>): List<ShapeHeatmap> {
        val kept = drawings.filter { it.moreCompliant && it.contours.any { c -> c.size >= 3 } }
        val boxes = kept.groupBy { it.participant }.mapValues { (_, own) ->
            val points = own.flatMap { d -> d.contours.flatten() }
            doubleArrayOf(points.minOf { it.x }, points.minOf { it.y }, points.maxOf { it.x }, points.maxOf { it.y })
        }
        val counts = LinkedHashMap<ElectrodeMask, IntArray>()
        val trials = HashMap<ElectrodeMask, Int>()
        for (drawing in kept) {
            val box = boxes.getValue(drawing.participant)
            val scaled = drawing.contours.filter { it.size >= 3 }.map { contour ->
                contour.map { p -> scale(p.x, box[0], box[2]) to scale(p.y, box[1], box[3]) }
            }
            val inside = fill(scaled)
            val count = counts.getOrPut(drawing.condition.mask) { IntArray(SIZE * SIZE) }
            for (i in inside.indices) if (inside[i]) count[i]++
            trials.merge(drawing.condition.mask, 1, Int::plus)
        }
        val max = counts.values.maxOfOrNull { it.max() } ?: 0
        return counts.map { (shape, count) ->
            ShapeHeatmap(shape, trials.getValue(shape), IntArray(count.size) { if (max == 0) 0 else (count[it] * 255.0 / max).roundToInt() })
        }
    }

    /** [v] from [low]..[high] to 0..SIZE; a degenerate box (one line) maps to the middle. */
    private fun scale(v: Double, low: Double, high: Double): Double = if (high > low) (v - low) / (high - low) * SIZE else SIZE / 2.0

    /** The pixels whose centres lie inside any of [contours] (even–odd rule within a contour), by scanlines. */
    private fun fill(contours: List<List<Pair<Double, Double>>>): BooleanArray {
        val inside = BooleanArray(SIZE * SIZE)
        for (contour in contours) {
            for (row in 0 until SIZE) {
                val y = row + 0.5
                val crossings = ArrayList<Double>()
                for (i in contour.indices) {
                    val (x0, y0) = contour[i]
                    val (x1, y1) = contour[(i + 1) % contour.size]
                    // Half-open in y, so a vertex on the scanline is counted once.
                    if ((y0 <= y) != (y1 <= y)) crossings += x0 + (y - y0) / (y1 - y0) * (x1 - x0)
                }
                crossings.sort()
                for (k in 0 until crossings.size - 1 step 2) {
                    val from = maxOf(0, kotlin.math.ceil(crossings[k] - 0.5).toInt())
                    val to = minOf(SIZE - 1, kotlin.math.floor(crossings[k + 1] - 0.5).toInt())
                    for (x in from..to) inside[row * SIZE + x] = true
                }
            }
        }
        return inside
    }
}
