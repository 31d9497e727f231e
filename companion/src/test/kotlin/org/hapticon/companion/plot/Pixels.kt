package org.hapticon.companion.plot

import java.awt.Color
import java.awt.image.BufferedImage
import kotlin.math.roundToInt

/** Pixel checks for plot tests; antialiasing blends edges, so searches look a few pixels around a point. */
object Pixels {
    fun isWhite(rgb: Int): Boolean = (rgb and 0xFFFFFF) == 0xFFFFFF

    /** Close to [color] in every channel (within [tolerance]). */
    fun near(rgb: Int, color: Color, tolerance: Int = 40): Boolean {
        val c = Color(rgb)
        return Math.abs(c.red - color.red) <= tolerance && Math.abs(c.green - color.green) <= tolerance &&
            Math.abs(c.blue - color.blue) <= tolerance
    }

    /** True when some pixel within [radius] of ([x], [y]) is near [color]. */
    fun anyNear(image: BufferedImage, x: Double, y: Double, color: Color, radius: Int = 2): Boolean {
        val cx = x.roundToInt()
        val cy = y.roundToInt()
        for (dx in -radius..radius) for (dy in -radius..radius) {
            val px = cx + dx
            val py = cy + dy
            if (px in 0 until image.width && py in 0 until image.height && near(image.getRGB(px, py), color)) return true
        }
        return false
    }

    /** Pixels of column [x] between rows [fromY] and [toY] (inclusive, any order) near [color]. */
    fun countInColumn(image: BufferedImage, x: Double, fromY: Double, toY: Double, color: Color): Int {
        val px = x.roundToInt()
        val range = minOf(fromY, toY).roundToInt()..maxOf(fromY, toY).roundToInt()
        return range.count { near(image.getRGB(px, it), color) }
    }
}
