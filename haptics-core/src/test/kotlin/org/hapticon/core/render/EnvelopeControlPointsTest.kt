package org.hapticon.core.render

import org.hapticon.core.HapticIcon
import org.hapticon.core.midiNoteToHz
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.hapticon.core.render.RenderAssertions.assertRejected
import org.junit.Test
import kotlin.math.sqrt

class EnvelopeControlPointsTest {
    private fun assertPoints(expected: List<Pair<Double, Long>>, actual: EnvelopeControlPoints, frequencyHz: Double) {
        assertEquals(expected.map { it.second }, actual.points.map { it.durationMillis })
        for ((point, want) in actual.points.zip(expected)) {
            assertEquals(want.first, point.amplitude, 1e-12)
            assertEquals(frequencyHz, point.frequencyHz, 0.0)
        }
    }

    /** The platform's rules: ≤ max points, every ramp ≥ 20 ms, ending at 0, lasting the rounded duration. */
    private fun assertValid(result: EnvelopeControlPoints, maxPoints: Int, totalMillis: Long) {
        assertTrue(result.points.size in 1..maxPoints)
        assertTrue(result.points.all { it.durationMillis >= 20 })
        assertTrue(result.points.all { it.amplitude in 0.0..1.0 })
        assertEquals(0.0, result.points.last().amplitude, 0.0)
        assertEquals(totalMillis, result.totalMillis)
    }

    @Test
    fun fit_hug_isItsThreeCornersExactly() {
        val result = EnvelopeControlPoints.fit(HapticIcon.HUG, EnvelopeModel.PAPER)
        assertPoints(listOf(0.5 to 1500L, 0.5 to 1000L, 0.0 to 500L), result, midiNoteToHz(50.0))
        assertEquals(0.0, result.fidelity.rmsError, 1e-12)
        assertEquals(0.0, result.fidelity.maxError, 1e-12)
        assertTrue(result.isRepresentable)
    }

    @Test
    fun fit_stroke_followsOverlappingRepetitionsExactly() {
        val result = EnvelopeControlPoints.fit(HapticIcon.STROKE, EnvelopeModel.PAPER)
        // Repetitions every 2.6 s overlap: the release of one and the attack of the next cross at 0.06.
        val expected = listOf(0.3 to 1000L, 0.3 to 1000L) +
            (1..3).flatMap { listOf(0.06 to 800L, 0.3 to 800L, 0.3 to 1000L) } +
            listOf(0.0 to 1000L)
        assertPoints(expected, result, midiNoteToHz(65.0))
        assertEquals(0.0, result.fidelity.rmsError, 1e-12)
        assertTrue(result.isRepresentable)
        assertValid(result, 16, 10_800)
    }

    @Test
    fun fit_knock_cannotFollowTwentyMillisecondPulses() {
        val result = EnvelopeControlPoints.fit(HapticIcon.KNOCK, EnvelopeModel.PAPER)
        // Ends of segments must lie on the envelope 20 ms apart: only the middle pulse is caught, as a
        // 40 ms triangle; the first and last pulses are lost.
        assertPoints(listOf(0.0 to 260L, 0.5 to 20L, 0.0 to 20L, 0.0 to 260L), result, midiNoteToHz(57.0))
        // Squared error (ms · amplitude²): two lost pulses of 10/3 each, plus 0.625 for the triangle.
        assertEquals(sqrt((2 * 10.0 / 3 + 0.625) / 560), result.fidelity.rmsError, 1e-5)
        assertEquals(0.5, result.fidelity.maxError, 1e-12)
        assertEquals(sqrt((2 * 10.0 / 3 + 0.625) / 10.0), result.relativeRmsError, 1e-4)
        assertFalse(result.isRepresentable)
        assertValid(result, 16, 560)
    }

    @Test
    fun fit_hit_usesTheWholeBudgetAndIsNotRepresentable() {
        val result = EnvelopeControlPoints.fit(HapticIcon.HIT, EnvelopeModel.PAPER)
        assertValid(result, 16, 1540)
        assertEquals(16, result.points.size)
        assertTrue(result.relativeRmsError > EnvelopeControlPoints.REPRESENTABLE_RELATIVE_ERROR)
        assertFalse(result.isRepresentable)
    }

    @Test
    fun fit_everyPresetAndModel_obeysThePlatformRules() {
        for (icon in HapticIcon.PRESETS) {
            for (model in EnvelopeModel.values()) {
                for (maxPoints in listOf(1, 2, 5, 16, 40)) {
                    val result = EnvelopeControlPoints.fit(icon, model, maxPoints)
                    assertValid(result, maxPoints, Math.round(icon.duration * 1000))
                    assertTrue(result.points.all { it.frequencyHz == icon.frequency })
                }
            }
        }
    }

    @Test
    fun fit_shorterMinimumSegment_followsKnockExactly() {
        val result = EnvelopeControlPoints.fit(HapticIcon.KNOCK, EnvelopeModel.PAPER, minSegmentMillis = 5)
        // Three trapezoids: 4 corners each, the first starting at the implicit 0 → 11 points.
        assertEquals(11, result.points.size)
        assertEquals(0.0, result.fidelity.rmsError, 1e-12)
        assertTrue(result.isRepresentable)
    }

    @Test
    fun fit_morePointsNeverFitWorse() {
        var previous = Double.POSITIVE_INFINITY
        for (maxPoints in 1..16) {
            val error = EnvelopeControlPoints.fit(HapticIcon.HIT, EnvelopeModel.PAPER, maxPoints = maxPoints).fidelity.rmsError
            assertTrue(error <= previous + 1e-12)
            previous = error
        }
    }

    @Test
    fun fit_singlePoint_isSilenceOverTheDuration() {
        val result = EnvelopeControlPoints.fit(HapticIcon.HUG, EnvelopeModel.PAPER, maxPoints = 1)
        assertPoints(listOf(0.0 to 3000L), result, midiNoteToHz(50.0))
        assertEquals(1.0, result.relativeRmsError, 1e-9)
        assertFalse(result.isRepresentable)
    }

    @Test
    fun fit_envelopeShorterThanOneSegment_hasNoPoints() {
        val result = EnvelopeControlPoints.fit({ 0.5 }, 0.015, 100.0)
        assertTrue(result.points.isEmpty())
        assertEquals(0L, result.totalMillis)
        assertEquals(0.5, result.fidelity.rmsError, 1e-12)
        assertFalse(result.isRepresentable)
    }

    @Test
    fun fit_instantAttack_startsWithARampFromZero() {
        // An envelope at 0.8 from t = 0 cannot jump there: the first ramp must take 20 ms.
        val result = EnvelopeControlPoints.fit({ t -> if (t < 0.2) 0.8 else 0.0 }, 0.3, 100.0)
        assertValid(result, 16, 300)
        assertEquals(20L, result.points.first().durationMillis)
        assertEquals(0.8, result.points.first().amplitude, 0.0)
    }

    @Test
    fun fit_invalidParameters_areRejected() {
        assertRejected("maxPoints must be in 1..256, was 0") { EnvelopeControlPoints.fit(HapticIcon.HUG, EnvelopeModel.PAPER, maxPoints = 0) }
        assertRejected("maxPoints must be in 1..256, was 257") { EnvelopeControlPoints.fit(HapticIcon.HUG, EnvelopeModel.PAPER, maxPoints = 257) }
        assertRejected("minSegmentMillis must be >= 1, was 0") { EnvelopeControlPoints.fit(HapticIcon.HUG, EnvelopeModel.PAPER, minSegmentMillis = 0) }
        assertRejected("frequencyHz must be finite and > 0, was NaN") { EnvelopeControlPoints.fit({ 0.5 }, 1.0, Double.NaN) }
        assertRejected("duration 31.0 s exceeds the 30.0 s safety cap") { EnvelopeControlPoints.fit({ 0.5 }, 31.0, 100.0) }
    }
}
