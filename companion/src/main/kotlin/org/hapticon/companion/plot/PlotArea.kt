package org.hapticon.companion.plot

/**
 * The rectangle of an image where data is drawn ([left], [top], [width] × [height] pixels) and its mapping
 * from time (0..[seconds]) and value ([minValue]..[maxValue], upwards) to pixel coordinates.
 * Pixel column c of the area shows times [c, c + 1) · seconds / width.
 */
class PlotArea(
    val left: Int,
    val top: Int,
    val width: Int,
    val height: Int,
    val seconds: Double,
    val minValue: Double,
    val maxValue: Double,
) {
    init {
        require(width > 0 && height > 0) { "plot area must not be empty" }
        require(seconds > 0.0) { "time span must be > 0 s, was $seconds" }
        require(maxValue > minValue) { "value range must not be empty" }
    }

    /** Right edge (exclusive), in pixels. */
    val right: Int get() = left + width

    /** Bottom edge (exclusive), in pixels. */
    val bottom: Int get() = top + height

    /** Horizontal pixel position of time [t] seconds. */
    fun x(t: Double): Double = left + t / seconds * width

    /** Vertical pixel position of [value]. */
    fun y(value: Double): Double = top + (maxValue - value) / (maxValue - minValue) * height

    /** Horizontal pixel position of the centre of column [column]. */
    fun columnX(column: Int): Double = left + column + 0.5
}
