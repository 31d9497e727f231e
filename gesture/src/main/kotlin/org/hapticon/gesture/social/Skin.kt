package org.hapticon.gesture.social

import kotlin.math.sqrt

/**
 * Where a touch-sensitive skin's elements are: element k's centroid at ([x]\[k], [y]\[k]), in the skin's own units.
 * The EIT-skin paper's reconstructed image has 729 finite elements (001_e790093bbd2e3cd3.txt:97) and gives touch
 * location as x and y "with their origin at the centre of the elbow" (001_e790093bbd2e3cd3.txt:108); a pressure grid's
 * elements are its cells.
 */
public class SkinLayout(x: DoubleArray, y: DoubleArray) {
    private val xs = x.copyOf()
    private val ys = y.copyOf()

    init {
        require(xs.isNotEmpty() && xs.size == ys.size) { "need one (x, y) per element, got ${xs.size} x and ${ys.size} y" }
        require(xs.all { it.isFinite() } && ys.all { it.isFinite() }) { "element positions must be finite" }
    }

    /** Number of elements. */
    public val size: Int get() = xs.size

    /** Element [k]'s x. */
    public fun x(k: Int): Double = xs[k]

    /** Element [k]'s y. */
    public fun y(k: Int): Double = ys[k]

    public companion object {
        /**
         * A [columns] × [rows] grid of cells (element index = row·columns + column) whose centres span
         * [x0]..[x1] along x and [y0]..[y1] along y (a single column or row sits at [x0] or [y0]).
         */
        public fun grid(columns: Int, rows: Int, x0: Double = 0.0, x1: Double = 1.0, y0: Double = 0.0, y1: Double = 1.0): SkinLayout {
            require(columns >= 1 && rows >= 1) { "a grid needs at least one column and row, got $columns x $rows" }
            fun at(i: Int, n: Int, a: Double, b: Double) = if (n == 1) a else a + (b - a) * i / (n - 1)
            return SkinLayout(
                DoubleArray(columns * rows) { at(it % columns, columns, x0, x1) },
                DoubleArray(columns * rows) { at(it / columns, rows, y0, y1) },
            )
        }
    }
}

/**
 * One acquisition step of a skin: at [timeSeconds], every element's pressure intensity in [elements] (the EIT skin's
 * conductivity change per finite element, difference imaging: 001_e790093bbd2e3cd3.txt:95, :107; a grid's cell
 * pressures) and the shoulder [joint] sensor's potential change from rest (001_e790093bbd2e3cd3.txt:79, :107); 0
 * where a skin has no joint sensor. [elements] is not copied: a producer hands each frame a fresh array.
 */
public class SkinFrame(public val timeSeconds: Double, public val elements: DoubleArray, public val joint: Double = 0.0)

/**
 * One frame of a single-pointer contact stream, as a touchscreen gives it: at [timeSeconds], contact of [intensity]
 * (pressure; 0 or less = no contact) centred at ([x], [y]) (0..1 across the pad) over [area] (the fraction of the pad
 * in contact, as Android's `MotionEvent.getSize` approximates it). [TouchPadSkin] draws it onto a skin of elements.
 */
public data class ContactFrame(val timeSeconds: Double, val intensity: Double, val x: Double, val y: Double, val area: Double)

/**
 * A touchscreen pad seen as a skin: a [columns] × [rows] grid over the pad (x and y 0..1), on which a [ContactFrame]
 * is drawn as a disc of its intensity and area (every element whose centre is within the disc, and always the one
 * under the finger, gets the intensity; the rest 0; no joint sensor). Ours: the paper's skin reconstructs an image;
 * a touchscreen reports one point and a size, and a disc is the least we can assume about the contact between.
 */
public class TouchPadSkin(public val columns: Int = DEFAULT_SIDE, public val rows: Int = DEFAULT_SIDE) {
    /** The pad's elements. */
    public val layout: SkinLayout = SkinLayout.grid(columns, rows)

    /** [contact] as a skin frame (a fresh element array). */
    public fun frame(contact: ContactFrame): SkinFrame {
        val elements = DoubleArray(layout.size)
        val intensity = contact.intensity
        if (intensity > 0.0 && intensity.isFinite()) {
            val radius = sqrt(maxOf(contact.area, 0.0) / Math.PI)
            val column = nearest(contact.x, columns)
            val row = nearest(contact.y, rows)
            for (k in elements.indices) {
                val dx = layout.x(k) - contact.x
                val dy = layout.y(k) - contact.y
                if (dx * dx + dy * dy <= radius * radius) elements[k] = intensity
            }
            elements[row * columns + column] = intensity
        }
        return SkinFrame(contact.timeSeconds, elements)
    }

    private fun nearest(v: Double, n: Int): Int = if (n == 1) 0 else Math.round(v.coerceIn(0.0, 1.0) * (n - 1)).toInt()

    public companion object {
        /** Elements per side of the pad: 16 × 16, a finger's width (~1 cm) on a phone-sized pad. */
        public const val DEFAULT_SIDE: Int = 16
    }
}
