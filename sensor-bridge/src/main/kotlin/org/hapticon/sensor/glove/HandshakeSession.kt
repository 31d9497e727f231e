package org.hapticon.sensor.glove

import org.hapticon.sensor.safety.SafetyLimits

/**
 * What one hand region's actuators should do: the interaction [pressureVolts], the glove actuator's
 * [actuatorDegrees], the LucidGloves force-feedback [servoValue] (null for the palm, which has no servo) and
 * the phone vibrator's [vibrationAmplitude]. Every value is checked against [SafetyLimits] when built.
 */
public data class RegionCommand(
    val region: HandRegion,
    val pressureVolts: Double,
    val actuatorDegrees: Double,
    val servoValue: Int?,
    val vibrationAmplitude: Int,
) {
    init {
        require(pressureVolts.isFinite() && pressureVolts >= 0.0) { "pressureVolts must be finite and >= 0, was $pressureVolts" }
        SafetyLimits.requireActuatorAngle(actuatorDegrees, region.actuatorLimitDegrees)
        if (region.lucidGlovesIndex == null) {
            require(servoValue == null) { "${region.label} has no LucidGloves servo, got $servoValue" }
        } else {
            require(servoValue != null) { "${region.label} needs a servo value" }
            SafetyLimits.requireServoValue(servoValue)
        }
        SafetyLimits.requireVibrationAmplitude(vibrationAmplitude)
    }

    public companion object {
        /** The command outside a handshake: no pressure, actuator at 0°, servo released, vibrator off. */
        public fun rest(region: HandRegion): RegionCommand =
            RegionCommand(region, 0.0, 0.0, region.lucidGlovesIndex?.let { SafetyLimits.SERVO_MIN }, SafetyLimits.VIBRATION_AMPLITUDE_MIN)
    }
}

/**
 * One step of a handshake for the receiving hand: whether the handshake is [active], what each side's
 * detector reported this step ([selfEvent], [partnerEvent]) and one [RegionCommand] per region in
 * [HandRegion.ALL] order.
 */
public data class HandshakeFrame(
    val active: Boolean,
    val selfEvent: HandshakeEvent,
    val partnerEvent: HandshakeEvent,
    val commands: List<RegionCommand>,
) {
    init {
        require(commands.map { it.region } == HandRegion.ALL) { "need one command per region in order, got ${commands.map { it.region }}" }
    }

    /** The command for [region]. */
    public fun command(region: HandRegion): RegionCommand = commands[region.ordinal]

    /**
     * A fresh array of the five LucidGloves force-feedback values, thumb … pinky (the order of
     * [HandRegion.lucidGlovesIndex]), as the LucidGloves force-feedback encoder takes them.
     */
    public fun lucidGlovesServoValues(): IntArray {
        val values = IntArray(LUCID_GLOVES_FINGERS)
        for (command in commands) {
            val index = command.region.lucidGlovesIndex ?: continue
            values[index] = command.servoValue ?: SafetyLimits.SERVO_MIN
        }
        return values
    }

    /** One amplitude for a phone's single vibrator: the largest region amplitude. */
    public val phoneAmplitude: Int get() = commands.maxOf { it.vibrationAmplitude }

    public companion object {
        /** Fingers in a LucidGloves force-feedback command. */
        public const val LUCID_GLOVES_FINGERS: Int = 5
    }
}

/**
 * The pressures one hand's actuators receive during a tele-handshake, step by step.
 *
 * Each step takes both hands' thumb and middle angles ("self" is the hand whose actuators are driven,
 * "partner" the other). Each hand has its own [HandshakeDetector] on its middle finger, and the handshake is
 * active while the **self** hand's detector is: pressure presentation starts when the wearer's own middle finger
 * exceeds the initiation angle θM0 = 30.9° (002_12aacdd60a14fec1.txt:138, "haptic feedback begins when this angle
 * is exceeded"; :169, "pressure presentation begins when the participant's finger flexion reaches an angle";
 * :170), whatever the partner's hand does. The partner's detector only reports [lastPartnerEvent] (for a display
 * of the partner's grip); their angles still weigh in through β once the wearer's own handshake has started.
 * While active, each region gets P from [model], an angle from its [tables] entry, a servo value and a vibration
 * amplitude; while inactive every region gets [RegionCommand.rest].
 *
 * Not thread-safe. [computeInto] is the allocation-free form for a streaming loop; [step] builds checked
 * value objects on top of it.
 */
public class HandshakeSession(
    /** The pressure formula. */
    public val model: InteractionPressureModel = InteractionPressureModel(),
    /** One actuator table per region in [HandRegion.ALL] order. */
    public val tables: List<ActuatorTable> = ActuatorTable.DEFAULTS,
    /** Pressure to phone vibration. */
    public val vibration: VibrationMapping = VibrationMapping(),
    startAboveDegrees: Double = HandshakeDetector.START_ABOVE_DEGREES,
    hysteresisDegrees: Double = HandshakeDetector.DEFAULT_HYSTERESIS_DEGREES,
) {
    init {
        require(tables.map { it.region } == HandRegion.ALL) { "need one table per region in order, got ${tables.map { it.region }}" }
    }

    private val selfDetector = HandshakeDetector(startAboveDegrees, hysteresisDegrees)
    private val partnerDetector = HandshakeDetector(startAboveDegrees, hysteresisDegrees)
    private val tableArray = tables.toTypedArray()
    private val regions = HandRegion.entries.toTypedArray()

    // Scratch for step(): it reuses computeInto so that both forms compute identical values.
    private val pressures = DoubleArray(regions.size)
    private val angles = DoubleArray(regions.size)
    private val servos = IntArray(regions.size)
    private val amplitudes = IntArray(regions.size)

    /** The event of the self hand's detector at the last step. */
    public var lastSelfEvent: HandshakeEvent = HandshakeEvent.NONE
        private set

    /** The event of the partner hand's detector at the last step. */
    public var lastPartnerEvent: HandshakeEvent = HandshakeEvent.NONE
        private set

    /** Whether the handshake was active at the last step: the self hand's middle finger past the threshold. */
    public val isActive: Boolean get() = selfDetector.isActive

    /**
     * Advances both detectors and writes, per region in [HandRegion.ALL] order, the pressure (V), actuator
     * angle (°), servo value (0..1000; 0 for the palm, which has none) and vibration amplitude (0..255).
     * Returns whether the handshake is active. Allocation-free.
     * @throws IllegalArgumentException when an angle is not finite or an array has fewer than 6 slots.
     */
    public fun computeInto(
        selfThumbDegrees: Double,
        selfMiddleDegrees: Double,
        partnerThumbDegrees: Double,
        partnerMiddleDegrees: Double,
        pressuresVolts: DoubleArray,
        actuatorDegrees: DoubleArray,
        servoValues: IntArray,
        vibrationAmplitudes: IntArray,
    ): Boolean {
        require(pressuresVolts.size >= regions.size && actuatorDegrees.size >= regions.size &&
            servoValues.size >= regions.size && vibrationAmplitudes.size >= regions.size) { "every array needs ${regions.size} slots" }
        // Validate before touching the detectors so a bad step leaves the session unchanged.
        require(selfThumbDegrees.isFinite() && partnerThumbDegrees.isFinite()) { "thumb angles must be finite" }
        require(selfMiddleDegrees.isFinite() && partnerMiddleDegrees.isFinite()) { "middle angles must be finite" }
        lastSelfEvent = selfDetector.update(selfMiddleDegrees)
        lastPartnerEvent = partnerDetector.update(partnerMiddleDegrees)
        val active = isActive
        if (!active) {
            for (i in regions.indices) {
                pressuresVolts[i] = 0.0
                actuatorDegrees[i] = 0.0
                servoValues[i] = SafetyLimits.SERVO_MIN
                vibrationAmplitudes[i] = SafetyLimits.VIBRATION_AMPLITUDE_MIN
            }
            return false
        }
        model.pressuresInto(selfThumbDegrees, selfMiddleDegrees, partnerThumbDegrees, partnerMiddleDegrees, pressuresVolts)
        for (i in regions.indices) {
            val table = tableArray[i]
            val angle = table.angleFor(pressuresVolts[i])
            actuatorDegrees[i] = angle
            servoValues[i] = if (regions[i].lucidGlovesIndex == null) SafetyLimits.SERVO_MIN else table.servoValueFor(angle)
            vibrationAmplitudes[i] = vibration.amplitudeFor(regions[i], pressuresVolts[i], true)
        }
        return true
    }

    /**
     * Advances the session by one step and returns the checked commands for every region.
     * @throws IllegalArgumentException when an angle is not finite.
     */
    public fun step(
        selfThumbDegrees: Double,
        selfMiddleDegrees: Double,
        partnerThumbDegrees: Double,
        partnerMiddleDegrees: Double,
    ): HandshakeFrame {
        val active = computeInto(selfThumbDegrees, selfMiddleDegrees, partnerThumbDegrees, partnerMiddleDegrees, pressures, angles, servos, amplitudes)
        val commands = regions.map { region ->
            val i = region.ordinal
            if (!active) {
                RegionCommand.rest(region)
            } else {
                RegionCommand(region, pressures[i], angles[i], if (region.lucidGlovesIndex == null) null else servos[i], amplitudes[i])
            }
        }
        return HandshakeFrame(active, lastSelfEvent, lastPartnerEvent, commands)
    }

    /** Ends any handshake in progress (both detectors). */
    public fun reset() {
        selfDetector.reset()
        partnerDetector.reset()
        lastSelfEvent = HandshakeEvent.NONE
        lastPartnerEvent = HandshakeEvent.NONE
    }
}
