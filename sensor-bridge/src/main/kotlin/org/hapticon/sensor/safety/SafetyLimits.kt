package org.hapticon.sensor.safety

import org.hapticon.core.HapticIcon
import org.hapticon.core.render.VibrationWaveform

/**
 * The one place for the hard limits on everything that drives a body: force-feedback servos, glove
 * actuators, electrotactile current and the phone's vibrator.
 *
 * Models clamp their outputs into these ranges, and every command value checks them again when it is
 * built, so a bug in a model cannot reach a person. Each `require…` helper returns its argument when it
 * is within the limit and otherwise throws [SafetyLimitException]; NaN and ±∞ are always refused.
 */
public object SafetyLimits {
    /** Lowest LucidGloves force-feedback value: no force (the firmware releases the servo). */
    public const val SERVO_MIN: Int = 0

    /** Highest LucidGloves force-feedback value: full force (the firmware's fully restricting position). */
    public const val SERVO_MAX: Int = 1000

    /** Largest actuator angle a finger region's calibration table may command, in degrees: the tele-handshake paper's finger motors' maximum (002_12aacdd60a14fec1.txt:112). */
    public const val FINGER_ACTUATOR_MAX_DEGREES: Double = 190.0

    /** Largest actuator angle the palm's calibration table may command, in degrees: the paper's palm motor maximum (002_12aacdd60a14fec1.txt:112). */
    public const val PALM_ACTUATOR_MAX_DEGREES: Double = 310.0

    /** Hard cap on electrotactile current, in milliamperes; no per-user calibration may exceed it. */
    public const val ELECTROTACTILE_MAX_MILLIAMPS: Double = 2.7

    /** Lowest vibration amplitude (off). */
    public const val VIBRATION_AMPLITUDE_MIN: Int = 0

    /** Highest vibration amplitude Android accepts ([VibrationWaveform.MAX_AMPLITUDE]). */
    public const val VIBRATION_AMPLITUDE_MAX: Int = VibrationWaveform.MAX_AMPLITUDE

    /** Longest a single vibration may last, in seconds ([HapticIcon.MAX_DURATION_SECONDS]). */
    public const val VIBRATION_MAX_SECONDS: Double = HapticIcon.MAX_DURATION_SECONDS

    /**
     * Returns [value] when it is a LucidGloves servo value in [SERVO_MIN]..[SERVO_MAX].
     * @throws SafetyLimitException otherwise.
     */
    public fun requireServoValue(value: Int): Int {
        if (value !in SERVO_MIN..SERVO_MAX) {
            throw SafetyLimitException("servo", "servo value must be in $SERVO_MIN..$SERVO_MAX, was $value")
        }
        return value
    }

    /**
     * Returns [degrees] when it is a finite actuator angle in [0, [maxDegrees]], where [maxDegrees] is the
     * calibration table's largest angle.
     * @throws SafetyLimitException when [degrees] is outside that range or not finite, or when [maxDegrees]
     *   is not in [0, [PALM_ACTUATOR_MAX_DEGREES]].
     */
    public fun requireActuatorAngle(degrees: Double, maxDegrees: Double): Double {
        requireActuatorMaximum(maxDegrees, PALM_ACTUATOR_MAX_DEGREES)
        if (!(degrees >= 0.0 && degrees <= maxDegrees)) {
            throw SafetyLimitException("actuatorAngle", "actuator angle must be in [0, $maxDegrees]°, was $degrees")
        }
        return degrees
    }

    /**
     * Returns [maxDegrees] when it is a finite angle in [0, [regionLimitDegrees]]: the check a calibration
     * table's largest angle passes ([FINGER_ACTUATOR_MAX_DEGREES] or [PALM_ACTUATOR_MAX_DEGREES]).
     * @throws SafetyLimitException otherwise.
     */
    public fun requireActuatorMaximum(maxDegrees: Double, regionLimitDegrees: Double): Double {
        if (!(maxDegrees >= 0.0 && maxDegrees <= regionLimitDegrees && regionLimitDegrees <= PALM_ACTUATOR_MAX_DEGREES)) {
            throw SafetyLimitException(
                "actuatorAngle",
                "actuator table maximum must be in [0, $regionLimitDegrees]° (hard limit $PALM_ACTUATOR_MAX_DEGREES°), was $maxDegrees",
            )
        }
        return maxDegrees
    }

    /**
     * Returns [milliamps] when it is a finite current in (0, [userMaxMilliamps]] and [userMaxMilliamps] is
     * itself within the hard cap, (0, [ELECTROTACTILE_MAX_MILLIAMPS]].
     * @throws SafetyLimitException when either is out of range or not finite.
     */
    public fun requireElectrotactileCurrent(milliamps: Double, userMaxMilliamps: Double): Double {
        requireElectrotactileUserMaximum(userMaxMilliamps)
        if (!(milliamps > 0.0 && milliamps <= userMaxMilliamps)) {
            throw SafetyLimitException(
                "electrotactileCurrent",
                "electrotactile current must be in (0, $userMaxMilliamps] mA (the user's calibrated maximum; " +
                    "hard cap $ELECTROTACTILE_MAX_MILLIAMPS mA), was $milliamps",
            )
        }
        return milliamps
    }

    /**
     * Returns [milliamps] when it is a finite per-user maximum in (0, [ELECTROTACTILE_MAX_MILLIAMPS]].
     * @throws SafetyLimitException otherwise.
     */
    public fun requireElectrotactileUserMaximum(milliamps: Double): Double {
        if (!(milliamps > 0.0 && milliamps <= ELECTROTACTILE_MAX_MILLIAMPS)) {
            throw SafetyLimitException(
                "electrotactileCurrent",
                "a user's electrotactile maximum must be in (0, $ELECTROTACTILE_MAX_MILLIAMPS] mA, was $milliamps",
            )
        }
        return milliamps
    }

    /**
     * Returns [amplitude] when it is in [VIBRATION_AMPLITUDE_MIN]..[VIBRATION_AMPLITUDE_MAX].
     * @throws SafetyLimitException otherwise.
     */
    public fun requireVibrationAmplitude(amplitude: Int): Int {
        if (amplitude !in VIBRATION_AMPLITUDE_MIN..VIBRATION_AMPLITUDE_MAX) {
            throw SafetyLimitException(
                "vibrationAmplitude",
                "vibration amplitude must be in $VIBRATION_AMPLITUDE_MIN..$VIBRATION_AMPLITUDE_MAX, was $amplitude",
            )
        }
        return amplitude
    }

    /**
     * Returns [seconds] when it is a finite vibration duration in (0, [VIBRATION_MAX_SECONDS]].
     * @throws SafetyLimitException otherwise.
     */
    public fun requireVibrationSeconds(seconds: Double): Double {
        if (!(seconds > 0.0 && seconds <= VIBRATION_MAX_SECONDS)) {
            throw SafetyLimitException(
                "vibrationDuration",
                "vibration duration must be in (0, $VIBRATION_MAX_SECONDS] s, was $seconds",
            )
        }
        return seconds
    }
}

/**
 * A value that would drive a body beyond a hard limit of [SafetyLimits] was refused. [limit] names the limit
 * (`servo`, `actuatorAngle`, `electrotactileCurrent`, `vibrationAmplitude`, `vibrationDuration`).
 */
public class SafetyLimitException(public val limit: String, message: String) : IllegalArgumentException(message)
