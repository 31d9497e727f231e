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

    /**
     * Whether this pattern has enough electrodes for a compliance grain to be felt: at least
     * [MIN_COMPLIANCE_ELECTRODES] (Shaping Compliance's pilot found 1–3 too weak: 003_8ca1dc8f53472543.txt:107). [org.hapticon.sensor.grains.FirmwareGrainParams]
     * and the compliance protocol refuse patterns below it; other uses (calibrating one electrode) may drive fewer.
     */
    public val isStrongEnoughForCompliance: Boolean get() = activeCount >= MIN_COMPLIANCE_ELECTRODES

    /** The indices (3·row + column) of the electrodes on, ascending: the time-division scan order. */
    public fun electrodes(): List<Int> = (0 until SIZE * SIZE).filter { bits and (1 shl it) != 0 }

    /** The pattern as 3 strings, top row first, `X` on and `.` off (as in the docs). */
    public fun rows(): List<String> = (0 until SIZE).map { row -> (0 until SIZE).joinToString("") { if (isOn(row, it)) "X" else "." } }

    /** The rows joined with `/`, e.g. `XXX/X.X/XXX`. */
    override fun toString(): String = rows().joinToString("/")

    public companion object {
        /** Electrodes per side. */
        public const val SIZE: Int = 3

        /** Fewest electrodes a compliance grain may drive: 4 (fewer felt too weak in Shaping Compliance's pilot, 003_8ca1dc8f53472543.txt:107). */
        public const val MIN_COMPLIANCE_ELECTRODES: Int = 4

        /** All nine electrodes: the whole-array calibration check. */
        public val ALL: ElectrodePattern = ElectrodePattern((1 shl (SIZE * SIZE)) - 1)

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

/**
 * The electrode conditions of Shaping Compliance (the electrotactile compliance illusion, CHI 2024) on its 3×3 array
 * (1.5 mm electrodes, 3 mm apart, the centre one over the FSR's centre: 003_8ca1dc8f53472543.txt:115, :117).
 *
 * From the paper's text: Task 1's four conditions are the "large square with 3×3 electrodes, small square (2×2),
 * vertical line (2×3), and horizontal line (3×2)" (003_8ca1dc8f53472543.txt:144), sizes written columns × rows (the
 * vertical line is the taller one); Task 2 adds a triangle (:171); squares have 4 or 9 electrodes, lines 6 and the
 * triangle 6, shapes vary in "orientations (horizontal, vertical, diagonal), relative positions (top, bottom, left,
 * right), and sizes" (:107). Which electrodes a 2-wide shape and the triangle take is shown only in Figure 5, whose
 * caption says the active electrodes are drawn beside each heatmap (:159, :177); that figure is not in the text, so
 * those placements are ours: the left columns and the top rows for the 2-wide shapes, and for the triangle a right
 * triangle whose hypotenuse is the array's diagonal (the text's "diagonal" orientation), right angle at the bottom left.
 * Every mask has at least [ElectrodePattern.MIN_COMPLIANCE_ELECTRODES] electrodes: fewer felt too weak in the
 * paper's pilot (:107).
 */
public enum class ElectrodeMask(
    /** The electrodes this mask drives. */
    public val pattern: ElectrodePattern,
) {
    /** The whole array, 9 electrodes ("3×3"): `XXX/XXX/XXX`. */
    LARGE_SQUARE(ElectrodePattern.of("XXX", "XXX", "XXX")),

    /** 2×2, 4 electrodes; the top-left corner is ours (figure only): `XX./XX./...`. */
    SMALL_SQUARE(ElectrodePattern.of("XX.", "XX.", "...")),

    /** 3 columns × 2 rows, 6 electrodes; the top two rows are ours (figure only): `XXX/XXX/...`. */
    HORIZONTAL_LINE(ElectrodePattern.of("XXX", "XXX", "...")),

    /** 2 columns × 3 rows, 6 electrodes; the left two columns are ours (figure only): `XX./XX./XX.`. */
    VERTICAL_LINE(ElectrodePattern.of("XX.", "XX.", "XX.")),

    /** Task 2's triangle, 6 electrodes: a right triangle along the diagonal, right angle bottom left (ours, figure only): `X../XX./XXX`. */
    TRIANGLE(ElectrodePattern.of("X..", "XX.", "XXX")),
}
