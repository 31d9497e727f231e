package org.hapticon.companion.plot

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test

class ModelComparisonPlotTest {
    private val image = ModelComparisonPlot.draw(HapticIcon.PRESETS, 44_100)

    @Test
    fun draw_fourPresets_isOnePanelEach() {
        assertEquals(1200, image.width)
        assertEquals(64 + 4 * 290, image.height)
        assertTrue(Pixels.isWhite(image.getRGB(2, 2)))
    }

    @Test
    fun draw_stroke_processingPeaksAtOneWhilePaperHoldsPointThree() {
        val area = ModelComparisonPlot.area(0, HapticIcon.STROKE.duration)
        assertTrue(Pixels.anyNear(image, area.x(1.0), area.y(1.0), PlotStyle.PROCESSING))
        assertTrue(Pixels.anyNear(image, area.x(1.5), area.y(0.3), PlotStyle.PAPER))
        assertFalse(Pixels.anyNear(image, area.x(1.0), area.y(1.0), PlotStyle.PAPER, radius = 4))
    }

    @Test
    fun draw_knock_processingSpikesToOneInTheThirdPanel() {
        val area = ModelComparisonPlot.area(2, HapticIcon.KNOCK.duration)
        assertTrue(Pixels.anyNear(image, area.x(0.005), area.y(1.0), PlotStyle.PROCESSING, radius = 3))
        assertTrue(Pixels.anyNear(image, area.x(0.010), area.y(0.5), PlotStyle.PAPER))
    }

    @Test
    fun draw_hit_modelsCoincideAtLevelOne() {
        // Level 1 makes Processing's sustain ramp flat: both envelopes are the same, paper drawn on top.
        val area = ModelComparisonPlot.area(1, HapticIcon.HIT.duration)
        assertTrue(Pixels.anyNear(image, area.x(0.05), area.y(1.0), PlotStyle.PAPER))
    }
}
