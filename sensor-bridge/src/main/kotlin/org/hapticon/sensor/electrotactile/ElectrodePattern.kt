package org.hapticon.sensor.electrotactile

/**
 * Which electrodes of a 3×3 array are driven. Electrodes are numbered row by row from the top left,
 * index = 3·row + column (0..8); [bits] has bit i set when electrode i is on. At least one must be on.
 */
public data class ElectrodePattern(val bits: Int) {
    init {
        require(bits in 1..ALL_BITS) { "a 3×3 pattern needs 1..9 electrodes on (bits 1..$ALL_BITS), was $bits" }
    }

    /**
     * Whether the electrode at [row], [column] (each 0..2) is on.
     * @throws IllegalArgumentException when either is outside 0..2.
     */
    public fun isOn(row: Int, column: Int): Boolean {
        require(row in 0 until SIZE && column in 0 until SIZE) { "row and column must be in 0..2, were $row, $column" }
        return bits and (1 shl (SIZE * row + column)) != 0
    }

    /** Number of electrodes on. */
    public val activeCount: Int get() = Integer.bitCount(bits)

    /** The pattern as 3 strings, top row first, `X` on and `.` off (as in the docs). */
    public fun rows(): List<String> = (0 until SIZE).map { row -> (0 until SIZE).joinToString("") { if (isOn(row, it)) "X" else "." } }

    /** The rows joined with `/`, e.g. `XXX/X.X/XXX`. */
    override fun toString(): String = rows().joinToString("/")

    public companion object {
        /** Electrodes per side. */
        public const val SIZE: Int = 3

        private const val ALL_BITS = (1 shl (SIZE * SIZE)) - 1

        /**
         * The pattern drawn by three rows of three characters, `X` (or `x`) on and `.` off, top row first.
         * @throws IllegalArgumentException when there are not 3 rows of 3 such characters or all are off.
         */
        public fun of(vararg rows: String): ElectrodePattern {
            require(rows.size == SIZE) { "need $SIZE rows, got ${rows.size}" }
            var bits = 0
            rows.forEachIndexed { row, text ->
                require(text.length == SIZE) { "row $row must have $SIZE characters, was \"$text\"" }
                text.forEachIndexed { column, c ->
                    when (c) {
                        'X', 'x' -> bits = bits or (1 shl (SIZE * row + column))
                        '.' -> Unit
                        else -> throw IllegalArgumentException("row $row: '$c' is neither X nor .")
                    }
                }
            }
            return ElectrodePattern(bits)
        }
    }
}

/** The study's named electrode masks on the 3×3 array. */
public enum class ElectrodeMask(
    /** The electrodes this mask drives. */
    public val pattern: ElectrodePattern,
) {
    /** The outline of the whole array, 8 electrodes: `XXX/X.X/XXX`. */
    LARGE_SQUARE(ElectrodePattern.of("XXX", "X.X", "XXX")),

    /** A 2×2 block in the top-left corner, 4 electrodes: `XX./XX./...` (a 3×3 array has no centred 2×2). */
    SMALL_SQUARE(ElectrodePattern.of("XX.", "XX.", "...")),

    /** The middle row, 3 electrodes: `.../XXX/...`. */
    HORIZONTAL_LINE(ElectrodePattern.of("...", "XXX", "...")),

    /** The middle column, 3 electrodes: `.X./.X./.X.`. */
    VERTICAL_LINE(ElectrodePattern.of(".X.", ".X.", ".X.")),

    /** A triangle outline, apex at the top centre and base along the bottom row, 6 electrodes: `.X./X.X/XXX`. */
    TRIANGLE(ElectrodePattern.of(".X.", "X.X", "XXX")),
}
