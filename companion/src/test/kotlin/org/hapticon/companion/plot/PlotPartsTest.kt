package org.hapticon.companion.plot

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

class PlotPartsTest {
    @Test
    fun ticks_strokeDuration_areWholeSeconds() {
        val ticks = Ticks.between(0.0, 10.8, maxTicks = 12)
        assertEquals((0..10).map { it.toDouble() }, ticks.values)
        assertEquals("10", ticks.label(10.0))
    }

    @Test
    fun ticks_knockDuration_areTenthsWithOneDecimal() {
        val ticks = Ticks.between(0.0, 0.56, maxTicks = 12)
        assertEquals(listOf("0.0", "0.1", "0.2", "0.3", "0.4", "0.5"), ticks.values.map(ticks::label))
    }

    @Test
    fun ticks_symmetricAmplitude_includeZeroAndTheEnds() {
        val ticks = Ticks.between(-1.0, 1.0, maxTicks = 5)
        assertEquals(listOf("-1.0", "-0.5", "0.0", "0.5", "1.0"), ticks.values.map(ticks::label))
    }

    @Test
    fun columnExtremes_keepsMinAndMaxPerColumn() {
        val columns = ColumnExtremes(3)
        columns.add(0.2, 0.5)
        columns.add(0.6, -0.9)
        columns.add(0.9, 0.1)
        columns.add(2.5, 0.3)
        assertTrue(columns.hasValues(0))
        assertEquals(-0.9, columns.minAt(0), 0.0)
        assertEquals(0.5, columns.maxAt(0), 0.0)
        assertFalse(columns.hasValues(1))
        assertEquals(0.3, columns.minAt(2), 0.0)
    }

    @Test
    fun columnExtremes_positionPastTheLastColumn_isClampedIntoIt() {
        val columns = ColumnExtremes(2)
        columns.add(2.0, 1.0)
        assertTrue(columns.hasValues(1))
    }

    @Test
    fun columnExtremes_draw_fillsTheMinMaxStrokeOfADenseColumn() {
        val area = PlotArea(left = 0, top = 0, width = 4, height = 21, seconds = 1.0, minValue = -1.0, maxValue = 1.0)
        val (image, g) = PlotStyle.canvas(4, 21)
        val columns = ColumnExtremes(4)
        for (value in listOf(0.0, 0.8, -0.8, 0.0)) columns.add(1.3, value) // many samples in column 1
        g.color = java.awt.Color.BLACK
        columns.draw(g, area)
        g.dispose()
        // Column 1 is dark from y(0.8) = 2 to y(-0.8) = 18; columns 0 and 3 stay white.
        for (y in 3..17) assertFalse("y=$y", Pixels.isWhite(image.getRGB(1, y)))
        for (y in 0 until 21) assertTrue(Pixels.isWhite(image.getRGB(3, y)))
    }

    @Test
    fun iconText_parameters_listEveryParameterInShortForm() {
        assertEquals(
            "attack 0.005 s · sustain 0.01 s · level 0.5 · release 0.005 s · note 57 (220.0 Hz) · period 0.27 s × 3 · 0.56 s in all",
            IconText.parameters(HapticIcon.KNOCK),
        )
        assertEquals(
            "attack 1.5 s · sustain 1 s · level 0.5 · release 0.5 s · note 50 (146.8 Hz) · once · 3 s in all",
            IconText.parameters(HapticIcon.HUG),
        )
    }
}
