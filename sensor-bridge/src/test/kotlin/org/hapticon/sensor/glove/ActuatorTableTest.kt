package org.hapticon.sensor.glove

import org.hapticon.sensor.safety.SafetyLimitException
import org.junit.Assert.assertEquals
import org.junit.Assert.assertThrows
import org.junit.Assert.fail
import org.junit.Test

class ActuatorTableTest {
    private val custom = ActuatorTable(HandRegion.INDEX, listOf(0.5, 1.0, 2.0), listOf(10.0, 20.0, 100.0))

    @Test
    fun defaultFor_thumb_isFiveEvenPointsFromPminToPmaxAndZeroTo190() {
        val table = ActuatorTable.defaultFor(HandRegion.THUMB)
        val pressures = table.pressuresVolts
        listOf(0.93, 1.34, 1.75, 2.16, 2.57).forEachIndexed { i, p -> assertEquals(p, pressures[i], 1e-15) }
        assertEquals(listOf(0.0, 47.5, 95.0, 142.5, 190.0), table.anglesDegrees)
        assertEquals(190.0, table.maxDegrees, 0.0)
    }

    @Test
    fun defaultFor_palm_reaches310Degrees() {
        assertEquals(listOf(0.0, 77.5, 155.0, 232.5, 310.0), ActuatorTable.defaultFor(HandRegion.PALM).anglesDegrees)
        assertEquals(HandRegion.ALL, ActuatorTable.DEFAULTS.map { it.region })
    }

    @Test
    fun angleFor_defaultThumbTable_isLinearInPressure() {
        val table = ActuatorTable.defaultFor(HandRegion.THUMB)
        // 190·(1.5 − 0.93)/1.64 = 108.3/1.64.
        assertEquals(66.03658536585365, table.angleFor(1.5), 1e-12)
    }

    @Test
    fun angleFor_betweenPoints_interpolatesLinearly() {
        assertEquals(15.0, custom.angleFor(0.75), 1e-12)
        assertEquals(60.0, custom.angleFor(1.5), 1e-12)
        assertEquals(20.0, custom.angleFor(1.0), 0.0)
    }

    @Test
    fun angleFor_outsideTheTable_isClampedToItsEnds() {
        assertEquals(10.0, custom.angleFor(0.0), 0.0)
        assertEquals(10.0, custom.angleFor(Double.NEGATIVE_INFINITY), 0.0)
        assertEquals(100.0, custom.angleFor(5.0), 0.0)
        assertEquals(100.0, custom.angleFor(Double.POSITIVE_INFINITY), 0.0)
    }

    @Test
    fun angleFor_nan_isRejected() {
        assertThrows(IllegalArgumentException::class.java) { custom.angleFor(Double.NaN) }
    }

    @Test
    fun servoValueFor_scalesTheTableMaximumTo1000() {
        assertEquals(600, custom.servoValueFor(60.0))
        assertEquals(150, custom.servoValueFor(15.0))
        assertEquals(1000, custom.servoValueFor(100.0))
        assertEquals(0, custom.servoValueFor(0.0))
    }

    @Test
    fun servoValueFor_roundsHalvesUpAndClamps() {
        // 1000·0.05/100 = 0.5 → 1; 0.049 → 0.49 → 0.
        assertEquals(1, custom.servoValueFor(0.05))
        assertEquals(0, custom.servoValueFor(0.049))
        assertEquals(1000, custom.servoValueFor(150.0))
        assertEquals(0, custom.servoValueFor(-5.0))
    }

    @Test
    fun servoValueFor_aTableThatNeverMoves_isZero() {
        assertEquals(0, ActuatorTable(HandRegion.RING, listOf(0.0, 1.0), listOf(0.0, 0.0)).servoValueFor(0.0))
    }

    @Test
    fun constructor_fingerTableBeyond190Degrees_isRefusedBySafetyLimits() {
        ActuatorTable(HandRegion.THUMB, listOf(0.0, 1.0), listOf(0.0, 190.0))
        try {
            ActuatorTable(HandRegion.THUMB, listOf(0.0, 1.0), listOf(0.0, Math.nextUp(190.0)))
            fail("accepted")
        } catch (e: SafetyLimitException) {
            assertEquals("actuatorAngle", e.limit)
        }
    }

    @Test
    fun constructor_palmTableAt310AcceptedAndBeyondRefused() {
        ActuatorTable(HandRegion.PALM, listOf(0.0, 1.0), listOf(0.0, 310.0))
        try {
            ActuatorTable(HandRegion.PALM, listOf(0.0, 1.0), listOf(0.0, 310.5))
            fail("accepted")
        } catch (e: SafetyLimitException) {
            assertEquals("actuatorAngle", e.limit)
        }
    }

    @Test
    fun constructor_malformedTables_areRejected() {
        assertThrows(IllegalArgumentException::class.java) { ActuatorTable(HandRegion.THUMB, listOf(1.0), listOf(0.0)) }
        assertThrows(IllegalArgumentException::class.java) { ActuatorTable(HandRegion.THUMB, listOf(1.0, 2.0), listOf(0.0)) }
        assertThrows(IllegalArgumentException::class.java) { ActuatorTable(HandRegion.THUMB, listOf(1.0, 1.0), listOf(0.0, 10.0)) }
        assertThrows(IllegalArgumentException::class.java) { ActuatorTable(HandRegion.THUMB, listOf(1.0, 2.0), listOf(20.0, 10.0)) }
        assertThrows(IllegalArgumentException::class.java) { ActuatorTable(HandRegion.THUMB, listOf(1.0, 2.0), listOf(-1.0, 10.0)) }
        assertThrows(IllegalArgumentException::class.java) { ActuatorTable(HandRegion.THUMB, listOf(1.0, Double.NaN), listOf(0.0, 10.0)) }
        assertThrows(IllegalArgumentException::class.java) { ActuatorTable(HandRegion.THUMB, listOf(1.0, 2.0), listOf(0.0, Double.POSITIVE_INFINITY)) }
    }
}
