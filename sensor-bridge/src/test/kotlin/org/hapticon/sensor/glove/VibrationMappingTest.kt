package org.hapticon.sensor.glove

import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test

class VibrationMappingTest {
    private val mapping = VibrationMapping()

    @Test
    fun amplitudeFor_inactive_isOff() {
        assertEquals(0, mapping.amplitudeFor(HandRegion.PALM, 4.0, active = false))
    }

    @Test
    fun amplitudeFor_atPminAndPmax_isTheFloorAndFullScale() {
        assertEquals(40, mapping.amplitudeFor(HandRegion.PALM, 1.23, active = true))
        assertEquals(255, mapping.amplitudeFor(HandRegion.PALM, 4.10, active = true))
    }

    @Test
    fun amplitudeFor_midRange_isRoundedHalfUp() {
        // Thumb midpoint 1.75 V: 40 + 215·0.5 = 147.5 → 148.
        assertEquals(148, mapping.amplitudeFor(HandRegion.THUMB, 1.75, active = true))
        // Palm at 2.665 V: n = 1.435/2.87 = 0.5 → 148; at 1.804 V: n = 0.2 → 40 + 43 = 83.
        assertEquals(83, mapping.amplitudeFor(HandRegion.PALM, 1.804, active = true))
    }

    @Test
    fun amplitudeFor_outsideTheRange_isClamped() {
        assertEquals(40, mapping.amplitudeFor(HandRegion.INDEX, 0.0, active = true))
        assertEquals(255, mapping.amplitudeFor(HandRegion.INDEX, 100.0, active = true))
        assertEquals(255, mapping.amplitudeFor(HandRegion.INDEX, Double.POSITIVE_INFINITY, active = true))
    }

    @Test
    fun amplitudeFor_aConfiguredFloor_startsThere() {
        // Floor 1: 1 + 254·0.5 = 128.
        assertEquals(128, VibrationMapping(1).amplitudeFor(HandRegion.THUMB, 1.75, active = true))
        assertEquals(255, VibrationMapping(255).amplitudeFor(HandRegion.THUMB, 0.93, active = true))
    }

    @Test
    fun amplitudeFor_nanOrAFloorOutside1To255_isRejected() {
        for (call in listOf(
            { mapping.amplitudeFor(HandRegion.THUMB, Double.NaN, active = true) },
            { VibrationMapping(0) },
            { VibrationMapping(256) },
        )) {
            try {
                call()
                fail("accepted")
            } catch (_: IllegalArgumentException) {
            }
        }
    }
}
