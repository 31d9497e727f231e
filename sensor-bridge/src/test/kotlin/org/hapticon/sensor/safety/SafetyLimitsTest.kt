package org.hapticon.sensor.safety

import org.hapticon.core.HapticIcon
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test

class SafetyLimitsTest {
    private fun assertRefused(limit: String, call: () -> Unit) {
        try {
            call()
            fail("accepted")
        } catch (e: SafetyLimitException) {
            assertEquals(limit, e.limit)
        }
    }

    @Test
    fun constants_areTheDocumentedLimits() {
        assertEquals(0, SafetyLimits.SERVO_MIN)
        assertEquals(1000, SafetyLimits.SERVO_MAX)
        assertEquals(190.0, SafetyLimits.FINGER_ACTUATOR_MAX_DEGREES, 0.0)
        assertEquals(310.0, SafetyLimits.PALM_ACTUATOR_MAX_DEGREES, 0.0)
        assertEquals(2.7, SafetyLimits.ELECTROTACTILE_MAX_MILLIAMPS, 0.0)
        assertEquals(255, SafetyLimits.VIBRATION_AMPLITUDE_MAX)
        assertEquals(HapticIcon.MAX_DURATION_SECONDS, SafetyLimits.VIBRATION_MAX_SECONDS, 0.0)
    }

    @Test
    fun requireServoValue_atBothLimits_returnsTheValue() {
        assertEquals(0, SafetyLimits.requireServoValue(0))
        assertEquals(1000, SafetyLimits.requireServoValue(1000))
    }

    @Test
    fun requireServoValue_justBeyondEitherLimit_isRefused() {
        assertRefused("servo") { SafetyLimits.requireServoValue(-1) }
        assertRefused("servo") { SafetyLimits.requireServoValue(1001) }
        assertRefused("servo") { SafetyLimits.requireServoValue(Int.MIN_VALUE) }
    }

    @Test
    fun requireActuatorAngle_atZeroAndAtTheTableMaximum_returnsTheAngle() {
        assertEquals(0.0, SafetyLimits.requireActuatorAngle(0.0, 190.0), 0.0)
        assertEquals(190.0, SafetyLimits.requireActuatorAngle(190.0, 190.0), 0.0)
        assertEquals(310.0, SafetyLimits.requireActuatorAngle(310.0, 310.0), 0.0)
    }

    @Test
    fun requireActuatorAngle_justBeyondTheTableMaximumOrBelowZero_isRefused() {
        assertRefused("actuatorAngle") { SafetyLimits.requireActuatorAngle(Math.nextUp(120.0), 120.0) }
        assertRefused("actuatorAngle") { SafetyLimits.requireActuatorAngle(-Double.MIN_VALUE, 120.0) }
    }

    @Test
    fun requireActuatorAngle_nanOrInfinite_isRefused() {
        assertRefused("actuatorAngle") { SafetyLimits.requireActuatorAngle(Double.NaN, 190.0) }
        assertRefused("actuatorAngle") { SafetyLimits.requireActuatorAngle(Double.POSITIVE_INFINITY, 190.0) }
        assertRefused("actuatorAngle") { SafetyLimits.requireActuatorAngle(Double.NEGATIVE_INFINITY, 190.0) }
        assertRefused("actuatorAngle") { SafetyLimits.requireActuatorAngle(10.0, Double.NaN) }
        assertRefused("actuatorAngle") { SafetyLimits.requireActuatorAngle(10.0, Double.POSITIVE_INFINITY) }
    }

    @Test
    fun requireActuatorMaximum_beyondTheRegionLimit_isRefused() {
        assertEquals(190.0, SafetyLimits.requireActuatorMaximum(190.0, SafetyLimits.FINGER_ACTUATOR_MAX_DEGREES), 0.0)
        assertRefused("actuatorAngle") { SafetyLimits.requireActuatorMaximum(Math.nextUp(190.0), SafetyLimits.FINGER_ACTUATOR_MAX_DEGREES) }
        assertRefused("actuatorAngle") { SafetyLimits.requireActuatorMaximum(Math.nextUp(310.0), SafetyLimits.PALM_ACTUATOR_MAX_DEGREES) }
        // A caller cannot widen the hard limit by passing a larger region limit.
        assertRefused("actuatorAngle") { SafetyLimits.requireActuatorMaximum(311.0, 400.0) }
    }

    @Test
    fun requireElectrotactileCurrent_atTheHardCap_returnsTheCurrent() {
        assertEquals(2.7, SafetyLimits.requireElectrotactileCurrent(2.7, 2.7), 0.0)
    }

    @Test
    fun requireElectrotactileCurrent_justAboveTheHardCap_isRefused() {
        assertRefused("electrotactileCurrent") { SafetyLimits.requireElectrotactileCurrent(Math.nextUp(2.7), 2.7) }
        assertRefused("electrotactileCurrent") { SafetyLimits.requireElectrotactileUserMaximum(Math.nextUp(2.7)) }
    }

    @Test
    fun requireElectrotactileCurrent_atAndJustAboveTheUserMaximum_acceptsThenRefuses() {
        assertEquals(1.2, SafetyLimits.requireElectrotactileCurrent(1.2, 1.2), 0.0)
        assertRefused("electrotactileCurrent") { SafetyLimits.requireElectrotactileCurrent(Math.nextUp(1.2), 1.2) }
    }

    @Test
    fun requireElectrotactileCurrent_zeroNegativeNanOrInfinite_isRefused() {
        for (bad in listOf(0.0, -0.1, Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY)) {
            assertRefused("electrotactileCurrent") { SafetyLimits.requireElectrotactileCurrent(bad, 2.7) }
            assertRefused("electrotactileCurrent") { SafetyLimits.requireElectrotactileCurrent(1.0, bad) }
        }
    }

    @Test
    fun requireVibrationAmplitude_atAndJustBeyondTheLimits_acceptsThenRefuses() {
        assertEquals(0, SafetyLimits.requireVibrationAmplitude(0))
        assertEquals(255, SafetyLimits.requireVibrationAmplitude(255))
        assertRefused("vibrationAmplitude") { SafetyLimits.requireVibrationAmplitude(-1) }
        assertRefused("vibrationAmplitude") { SafetyLimits.requireVibrationAmplitude(256) }
    }

    @Test
    fun requireVibrationSeconds_atAndJustBeyondTheCap_acceptsThenRefuses() {
        assertEquals(30.0, SafetyLimits.requireVibrationSeconds(30.0), 0.0)
        assertEquals(Double.MIN_VALUE, SafetyLimits.requireVibrationSeconds(Double.MIN_VALUE), 0.0)
        assertRefused("vibrationDuration") { SafetyLimits.requireVibrationSeconds(Math.nextUp(30.0)) }
        assertRefused("vibrationDuration") { SafetyLimits.requireVibrationSeconds(0.0) }
    }

    @Test
    fun requireVibrationSeconds_nanOrInfinite_isRefused() {
        assertRefused("vibrationDuration") { SafetyLimits.requireVibrationSeconds(Double.NaN) }
        assertRefused("vibrationDuration") { SafetyLimits.requireVibrationSeconds(Double.POSITIVE_INFINITY) }
        assertRefused("vibrationDuration") { SafetyLimits.requireVibrationSeconds(Double.NEGATIVE_INFINITY) }
    }

    @Test
    fun safetyLimitException_isAnIllegalArgumentExceptionWithTheMessage() {
        try {
            SafetyLimits.requireServoValue(1001)
            fail("accepted")
        } catch (e: IllegalArgumentException) {
            assertEquals("servo value must be in 0..1000, was 1001", e.message)
        }
    }
}
