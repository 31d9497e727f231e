package org.hapticon.sensor.glove

import org.hapticon.sensor.safety.SafetyLimits

/**
 * A region of the hand that receives interaction pressure during a tele-handshake, with the tele-handshake paper's
 * parameters: how much the own grip ([selfWeight], α) and the partner's grip ([partnerWeight], β) contribute
 * (Tables 3 and 5, 002_12aacdd60a14fec1.txt:271-278, :283-286), and the pressure range
 * [minPressureVolts]..[maxPressureVolts] (Tables 2 and 4, :263-270, :279-282; the paper measured pressure as an FSR
 * voltage, :158, so pressures are in volts throughout). α + β = 1 for every region. The paper's seven stimulus
 * points (:90-93) are six actuators: the palm's two regions share one motor and one averaged table (:118, :162).
 *
 * [actuatorLimitDegrees] is the hard safety limit on the region's actuator ([SafetyLimits]);
 * [lucidGlovesIndex] is the finger's position in a LucidGloves force-feedback command (thumb 0 … pinky 4),
 * or null for the palm, which has no LucidGloves servo.
 */
public enum class HandRegion(
    public val selfWeight: Double,
    public val partnerWeight: Double,
    public val minPressureVolts: Double,
    public val maxPressureVolts: Double,
    public val actuatorLimitDegrees: Double,
    public val lucidGlovesIndex: Int?,
) {
    /** Thumb: α 0.77, β 0.23, 0.93–2.57 V. */
    THUMB(0.77, 0.23, 0.93, 2.57, SafetyLimits.FINGER_ACTUATOR_MAX_DEGREES, 0),

    /** Index finger: α 0.70, β 0.30, 0.37–1.29 V. */
    INDEX(0.70, 0.30, 0.37, 1.29, SafetyLimits.FINGER_ACTUATOR_MAX_DEGREES, 1),

    /** Middle finger: α 0.82, β 0.18, 0.62–2.30 V. */
    MIDDLE(0.82, 0.18, 0.62, 2.30, SafetyLimits.FINGER_ACTUATOR_MAX_DEGREES, 2),

    /** Ring finger: α 0.69, β 0.31, 0.19–1.23 V. */
    RING(0.69, 0.31, 0.19, 1.23, SafetyLimits.FINGER_ACTUATOR_MAX_DEGREES, 3),

    /** Little finger ("pinkie" in the study): α 0.67, β 0.33, 0.33–1.66 V. */
    PINKY(0.67, 0.33, 0.33, 1.66, SafetyLimits.FINGER_ACTUATOR_MAX_DEGREES, 4),

    /** Palm: α 0.17, β 0.83, 1.23–4.10 V; actuated up to 310° and without a LucidGloves servo. */
    PALM(0.17, 0.83, 1.23, 4.10, SafetyLimits.PALM_ACTUATOR_MAX_DEGREES, null),
    ;

    /** Width of the pressure range, Pmax − Pmin, in volts. */
    public val pressureRangeVolts: Double get() = maxPressureVolts - minPressureVolts

    /** The lower-case name used in CSV headers and reports (`thumb`, …, `palm`). */
    public val label: String get() = name.lowercase()

    public companion object {
        /** The regions in command order: thumb, index, middle, ring, pinky, palm. */
        public val ALL: List<HandRegion> = entries.toList()
    }
}
