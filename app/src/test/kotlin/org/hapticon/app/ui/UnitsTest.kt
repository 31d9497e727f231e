package org.hapticon.app.ui

import org.junit.Assert.assertEquals
import org.junit.Test

class UnitsTest {
    @Test
    fun numberAndUnit_areJoinedByANoBreakSpace() {
        assertEquals(
            "16 points, 20\u00A0ms–1\u00A0s each, 16\u00A0s in all",
            keepUnitsWithNumbers("16 points, 20 ms–1 s each, 16 s in all"),
        )
        assertEquals("plays 175\u00A0Hz, 2.700\u00A0mA, 80\u00A0%", keepUnitsWithNumbers("plays 175 Hz, 2.700 mA, 80 %"))
    }

    @Test
    fun wordsThatMerelyStartLikeAUnit_areLeftAlone() {
        // "3 seconds", "2 species", "1 Hzs": a unit must end the word.
        assertEquals("3 seconds, 2 species, 1 Hzs", keepUnitsWithNumbers("3 seconds, 2 species, 1 Hzs"))
        assertEquals("", keepUnitsWithNumbers(""))
    }
}
