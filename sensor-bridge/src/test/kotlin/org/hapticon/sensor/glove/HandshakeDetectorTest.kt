package org.hapticon.sensor.glove

import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test

class HandshakeDetectorTest {
    @Test
    fun update_exactlyAtTheThreshold_doesNotStart() {
        val detector = HandshakeDetector()
        assertEquals(HandshakeEvent.NONE, detector.update(30.9))
        assertFalse(detector.isActive)
    }

    @Test
    fun update_justAboveTheThreshold_starts() {
        val detector = HandshakeDetector()
        assertEquals(HandshakeEvent.STARTED, detector.update(Math.nextUp(30.9)))
        assertTrue(detector.isActive)
        assertEquals(HandshakeEvent.NONE, detector.update(90.0))
    }

    @Test
    fun update_withinTheHysteresisBand_staysActive() {
        val detector = HandshakeDetector()
        detector.update(40.0)
        assertEquals(28.9, detector.endAtOrBelowDegrees, 0.0)
        assertEquals(HandshakeEvent.NONE, detector.update(30.0))
        assertEquals(HandshakeEvent.NONE, detector.update(Math.nextUp(28.9)))
        assertTrue(detector.isActive)
    }

    @Test
    fun update_atTheEndThreshold_endsAndARiseToTheStartThresholdDoesNotRestart() {
        val detector = HandshakeDetector()
        detector.update(40.0)
        assertEquals(HandshakeEvent.ENDED, detector.update(28.9))
        assertFalse(detector.isActive)
        assertEquals(HandshakeEvent.NONE, detector.update(30.9))
        assertEquals(HandshakeEvent.STARTED, detector.update(31.0))
    }

    @Test
    fun update_withoutHysteresis_endsAtTheStartThreshold() {
        val detector = HandshakeDetector(hysteresisDegrees = 0.0)
        detector.update(31.0)
        assertEquals(HandshakeEvent.ENDED, detector.update(30.9))
    }

    @Test
    fun update_nonFiniteAngle_isRejectedAndLeavesTheStateAlone() {
        val detector = HandshakeDetector()
        detector.update(40.0)
        for (bad in listOf(Double.NaN, Double.NEGATIVE_INFINITY)) {
            try {
                detector.update(bad)
                fail("accepted $bad")
            } catch (_: IllegalArgumentException) {
            }
        }
        assertTrue(detector.isActive)
    }

    @Test
    fun reset_endsAnActiveHandshakeSilently() {
        val detector = HandshakeDetector()
        detector.update(40.0)
        detector.reset()
        assertFalse(detector.isActive)
        assertEquals(HandshakeEvent.STARTED, detector.update(40.0))
    }

    @Test
    fun constructor_negativeOrNonFiniteHysteresis_isRejected() {
        for (bad in listOf(-0.1, Double.NaN, Double.POSITIVE_INFINITY)) {
            try {
                HandshakeDetector(hysteresisDegrees = bad)
                fail("accepted $bad")
            } catch (_: IllegalArgumentException) {
            }
        }
    }
}
