package org.hapticon.gesture.extraction

import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Test

class PiecewiseLinearFitTest {
    @Test fun recoversAnExactTrapezoid() {
        val truth = Trapezoid(100, 150, 400, 520, 0.8, 0.0, 1.0)
        val y = DoubleArray(700) { truth.valueAt(it) }
        val fit = PiecewiseLinearFit.fit(y)
        assertEquals(listOf(100, 150, 400, 520), listOf(fit.start, fit.attackEnd, fit.sustainEnd, fit.releaseEnd))
        assertEquals(0.8, fit.level, 1e-12)
        assertEquals(0.0, fit.rmsError, 1e-9)
        assertEquals(1.0, fit.rSquared, 1e-12)
    }

    @Test fun findsAStepAndATruncatedRelease() {
        // Attack 0 (a step at 10) and a recording that ends mid-sustain.
        val y = DoubleArray(50) { if (it >= 10) 0.5 else 0.0 }
        val fit = PiecewiseLinearFit.fit(y)
        assertEquals(10, fit.start)
        assertEquals(10, fit.attackEnd)
        assertEquals(0.5, fit.level, 1e-12)
        assertEquals(1.0, fit.rSquared, 1e-12)
    }

    @Test fun aFlatZeroEnvelopeFitsLevelZeroAndBadInputIsRejected() {
        val fit = PiecewiseLinearFit.fit(DoubleArray(10))
        assertEquals(0.0, fit.level, 0.0)
        assertEquals(0.0, fit.rSquared, 0.0)
        assertThrows(IllegalArgumentException::class.java) { PiecewiseLinearFit.fit(DoubleArray(1)) }
        val nan = assertThrows(IllegalArgumentException::class.java) { PiecewiseLinearFit.fit(doubleArrayOf(0.0, Double.NaN)) }
        assertEquals("envelope holds a non-finite value", nan.message)
    }
}
