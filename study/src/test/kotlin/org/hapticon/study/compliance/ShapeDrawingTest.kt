package org.hapticon.study.compliance

import org.hapticon.sensor.electrotactile.ElectrodeMask
import org.hapticon.sensor.electrotactile.ElectrodePattern
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class ShapeDrawingTest {
    private fun p(x: Double, y: Double) = DrawingPoint(x, y)
    private fun square(x0: Double, y0: Double, x1: Double, y1: Double) = listOf(p(x0, y0), p(x1, y0), p(x1, y1), p(x0, y1))

    @Test
    fun contours_encodeAndDecode_withoutCommas() {
        val contours = listOf(square(0.1, 0.2, 0.5, 0.6), listOf(p(0.7, 0.7), p(0.9, 0.7), p(0.8, 0.95)))
        val text = ShapeDrawings.encode(contours)
        assertEquals("0.1000:0.2000 0.5000:0.2000 0.5000:0.6000 0.1000:0.6000|0.7000:0.7000 0.9000:0.7000 0.8000:0.9500", text)
        assertFalse(text.contains(','))
        assertEquals(contours, ShapeDrawings.decode(text))
        assertEquals(emptyList<List<DrawingPoint>>(), ShapeDrawings.decode(""))
        try {
            ShapeDrawings.decode("0.1:0.2 0.3")
            fail("accepted")
        } catch (e: IllegalArgumentException) {
            assertEquals("not a drawing point: '0.3' (expected x:y)", e.message)
        }
    }

    @Test
    fun heatmap_isScaledToEachParticipantsBox_filled_andThresholdedAtHalf() {
        // Ann draws on the whole area, Bob on its top-left quarter only: each is scaled to his own bounding box, so both
        // drawings of the small square land on the same pixels.
        val drawings = listOf(
            ShapeDrawing("ann", 0, ComplianceCondition(39, ElectrodeMask.LARGE_SQUARE), true, listOf(square(0.0, 0.0, 1.0, 1.0))),
            ShapeDrawing("ann", 0, ComplianceCondition(39, ElectrodeMask.SMALL_SQUARE), true, listOf(square(0.0, 0.0, 0.5, 0.5))),
            ShapeDrawing("bob", 0, ComplianceCondition(39, ElectrodeMask.LARGE_SQUARE), true, listOf(square(0.0, 0.0, 0.5, 0.5))),
            ShapeDrawing("bob", 0, ComplianceCondition(39, ElectrodeMask.SMALL_SQUARE), true, listOf(square(0.0, 0.0, 0.25, 0.25))),
            // Felt less compliant than the desk: left out, as the paper removed its one such trial.
            ShapeDrawing("bob", 1, ComplianceCondition(39, ElectrodeMask.SMALL_SQUARE), false, listOf(square(0.3, 0.3, 0.5, 0.5))),
        )
        val maps = ShapeDrawings.heatmaps(drawings)
        assertEquals(listOf(ElectrodeMask.LARGE_SQUARE, ElectrodeMask.SMALL_SQUARE), maps.map { it.shape })
        val (large, small) = maps
        assertEquals(2, small.drawings)
        // Both participants on every pixel of the large square: the brightest count, 255.
        assertEquals(255, large.level(0, 0))
        assertEquals(255, large.level(339, 339))
        // The small square fills 0..170 for both: 255 there, nothing outside.
        assertEquals(255, small.level(169, 169))
        assertEquals(0, small.level(171, 100))
        assertTrue(small.shown(10, 10))
        assertEquals(ElectrodePattern.of("XXX", "XXX", "XXX"), large.feltCells())
        // 170 of 340 covers cell 0 fully and half of the next (not "most"): the top-left cell only.
        assertEquals(ElectrodePattern.of("X..", "...", "..."), small.feltCells())
        assertNull(ShapeDrawings.heatmaps(drawings.takeLast(1)).singleOrNull()?.feltCells())
    }

    @Test
    fun answersCsv_roundTripsBothTasks_andNamesABadLine() {
        val t1 = ComplianceStudy.PROTOCOL.trials(0)[4]
        val t2 = ComplianceStudy.SHAPES_PROTOCOL.trials(0)[2]
        val text = ComplianceAnswersCsv.HEADER + "\n" +
            ComplianceAnswersCsv.ratingRow(ComplianceStudy.PROTOCOL, "p7", t1, -1.5) + "\n\n" +
            ComplianceAnswersCsv.drawingRow(ComplianceStudy.SHAPES_PROTOCOL, "p7", t2, true, listOf(square(0.1, 0.1, 0.4, 0.4))) + "\n"
        val read = ComplianceAnswersCsv.read(text, "p7.csv")
        assertEquals(listOf(MagnitudeEstimate("p7", t1.repetition, t1.condition, -1.5)), read.ratings)
        assertEquals(listOf(ShapeDrawing("p7", t2.repetition, t2.condition, true, listOf(square(0.1, 0.1, 0.4, 0.4)))), read.drawings)
        assertTrue(text.lines()[1].startsWith("shaping-compliance,p7,5,1,"))
        try {
            ComplianceAnswersCsv.read(text.replace("-1.5", "x"), "p7.csv")
            fail("accepted")
        } catch (e: IllegalArgumentException) {
            assertEquals("p7.csv:2: rating 'x' is not a number", e.message)
        }
    }
}
