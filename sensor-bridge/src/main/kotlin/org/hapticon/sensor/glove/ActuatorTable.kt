package org.hapticon.sensor.glove

import org.hapticon.sensor.safety.SafetyLimits
import kotlin.math.floor

/**
 * A per-region calibration table from interaction pressure (V) to actuator angle (°), read by linear
 * interpolation between its points (as the tele-handshake paper reads its data table, 002_12aacdd60a14fec1.txt:118)
 * and clamped to them: pressures below the first point give the first angle, above the last point the last angle.
 * So the table's largest angle, [maxDegrees], bounds every output, and the table itself must lie within the region's
 * hard limit (190° for fingers, 310° for the palm: the paper's maximum motor angles, :112).
 *
 * Pressures must be finite and strictly increasing; angles finite, ≥ 0 and non-decreasing (more pressure
 * never moves the actuator back), at least 2 points.
 */
public class ActuatorTable(
    /** The region this table drives; its [HandRegion.actuatorLimitDegrees] bounds the angles. */
    public val region: HandRegion,
    pressuresVolts: List<Double>,
    anglesDegrees: List<Double>,
) {
    private val pressures: DoubleArray = pressuresVolts.toDoubleArray()
    private val angles: DoubleArray = anglesDegrees.toDoubleArray()

    init {
        require(pressures.size == angles.size) { "need as many angles as pressures, got ${angles.size} and ${pressures.size}" }
        require(pressures.size >= 2) { "need at least 2 points, got ${pressures.size}" }
        for (i in pressures.indices) {
            require(pressures[i].isFinite()) { "pressure $i must be finite, was ${pressures[i]}" }
            require(angles[i] >= 0.0 && angles[i].isFinite()) { "angle $i must be finite and >= 0°, was ${angles[i]}" }
            if (i > 0) {
                require(pressures[i] > pressures[i - 1]) { "pressures must increase strictly, point $i: ${pressures[i]} after ${pressures[i - 1]}" }
                require(angles[i] >= angles[i - 1]) { "angles must not decrease, point $i: ${angles[i]} after ${angles[i - 1]}" }
            }
        }
        SafetyLimits.requireActuatorMaximum(angles.last(), region.actuatorLimitDegrees)
    }

    /** The table's pressures in volts, increasing. */
    public val pressuresVolts: List<Double> get() = pressures.toList()

    /** The table's angles in degrees, non-decreasing. */
    public val anglesDegrees: List<Double> get() = angles.toList()

    /** The largest angle this table can command: its last angle. */
    public val maxDegrees: Double get() = angles[angles.size - 1]

    /**
     * The actuator angle for [pressureVolts], interpolated linearly and clamped to the table. Allocation-free.
     * @throws IllegalArgumentException when [pressureVolts] is NaN.
     */
    public fun angleFor(pressureVolts: Double): Double {
        require(!pressureVolts.isNaN()) { "pressure must not be NaN" }
        val last = pressures.size - 1
        if (pressureVolts <= pressures[0]) return angles[0]
        if (pressureVolts >= pressures[last]) return angles[last]
        // Tables are short (a handful of points): a linear scan beats a binary search here.
        var i = 1
        while (pressures[i] < pressureVolts) i++
        val fraction = (pressureVolts - pressures[i - 1]) / (pressures[i] - pressures[i - 1])
        return angles[i - 1] + fraction * (angles[i] - angles[i - 1])
    }

    /**
     * The LucidGloves force-feedback value for an actuator angle of [degrees]: round(1000·θ/[maxDegrees])
     * (halves up), clamped to 0..1000, so the table's travel maps onto the servo's full travel; 0 when the
     * table's maximum is 0°.
     * @throws IllegalArgumentException when [degrees] is NaN.
     */
    public fun servoValueFor(degrees: Double): Int {
        require(!degrees.isNaN()) { "degrees must not be NaN" }
        val max = maxDegrees
        if (max <= 0.0) return SafetyLimits.SERVO_MIN
        val scaled = floor(SafetyLimits.SERVO_MAX * degrees / max + 0.5)
        return scaled.coerceIn(SafetyLimits.SERVO_MIN.toDouble(), SafetyLimits.SERVO_MAX.toDouble()).toInt()
    }

    override fun equals(other: Any?): Boolean =
        other is ActuatorTable && other.region == region && other.pressures.contentEquals(pressures) && other.angles.contentEquals(angles)

    override fun hashCode(): Int = (region.hashCode() * 31 + pressures.contentHashCode()) * 31 + angles.contentHashCode()

    /** A debug representation listing the points. */
    override fun toString(): String =
        "ActuatorTable(${region.label}: ${pressures.indices.joinToString { "${pressures[it]} V→${angles[it]}°" }})"

    public companion object {
        /** Points in the default tables. */
        public const val DEFAULT_POINTS: Int = 5

        /**
         * The default table for [region]: a placeholder until the actuator is calibrated, not measured data. The
         * paper's table (pressure read every 10° from the band's touch to 190°/310°, averaged over three people and
         * two runs, 002_12aacdd60a14fec1.txt:101-118) exists only as its Figure 10 (:241), whose values are not in
         * the text. Ours: 5 points evenly spaced from Pmin to Pmax whose angles rise linearly from 0° to the
         * region's limit (190° for fingers, 310° for the palm), i.e. θ = limit·(P − Pmin)/(Pmax − Pmin).
         */
        public fun defaultFor(region: HandRegion): ActuatorTable {
            val steps = DEFAULT_POINTS - 1
            val pressures = List(DEFAULT_POINTS) { region.minPressureVolts + region.pressureRangeVolts * it / steps }
            val angles = List(DEFAULT_POINTS) { region.actuatorLimitDegrees * it / steps }
            return ActuatorTable(region, pressures, angles)
        }

        /** The default tables of every region, in [HandRegion.ALL] order. */
        public val DEFAULTS: List<ActuatorTable> = HandRegion.ALL.map { defaultFor(it) }
    }
}
