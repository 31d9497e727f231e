package org.hapticon.sensor.glove

/** Sends the wearer's own thumb and middle angles to a partner elsewhere (the chat's network partner). */
public fun interface HandPoseSink {
    /** Sends one pose, in degrees. */
    public fun send(thumbDegrees: Double, middleDegrees: Double)
}

/**
 * The tele-handshake loop of one glove, sample by sample, as the flex-sensor glove tele-handshake paper runs it
 * ("Tele Haptic Handshake Using Distributed Pressure Presentation Device and Mutual Interaction Pressure Model",
 * Electronics 14(3):537, 2025, doi:10.3390/electronics14030537; docs/sensor-models.md, "Glove model"): each divider reading becomes an angle through the wearer's
 * [FlexCalibration] (a faulty finger counts as open, 0°, which releases the partner's actuators rather than
 * squeezing them); the [partner]'s angles are read at the same instant; [HandshakeSession] starts the handshake
 * when the wearer's own middle finger exceeds the paper's 30.9° (002_12aacdd60a14fec1.txt:170) and mixes both hands into each region's interaction
 * pressure P = [α/2·nT(self) + α/2·nM(self) + β/2·nT(partner) + β/2·nM(partner)]·(Pmax − Pmin) + Pmin with the
 * paper's per-region α, β, Pmin, Pmax ([HandRegion]). From the pressures it drives:
 *
 * - a LucidGloves glove's five servos through [ForceFeedbackStream] (changes only, at most 20 commands/s,
 *   released at once when the handshake ends), while [forceFeedbackOn];
 * - the phone's vibrator: [onSample] returns the largest region amplitude ([VibrationMapping]), 0 outside a
 *   handshake, for the caller to play;
 * - the wearer's own pose to a [poseSink] (a network partner), at most every [poseIntervalNanos].
 *
 * Not thread-safe: the caller runs [onSample], [releaseForceFeedback] and the read-outs under one lock (the app's
 * view model does, between the glove's reading thread and the UI). Allocation-free per sample.
 */
public class HandshakeLoop(
    private val divider: FlexDivider,
    private val forceFeedback: ForceFeedbackSink,
    private val session: HandshakeSession = HandshakeSession(),
    private val feedback: ForceFeedbackStream = ForceFeedbackStream(),
    private val poseIntervalNanos: Long = POSE_INTERVAL_NANOS,
) {
    private val regions = HandRegion.entries.size
    private val pressures = DoubleArray(regions)
    private val actuatorAngles = DoubleArray(regions)
    private val servos = IntArray(regions)
    private val amplitudes = IntArray(regions)
    private val partnerAngles = DoubleArray(2)
    private var lastPoseSentNanos = Long.MIN_VALUE / 2

    /** The wearer's thumb calibration (the default until they calibrate). */
    @Volatile public var thumbCalibration: FlexCalibration = FlexCalibration.THUMB_DEFAULT

    /** The wearer's middle-finger calibration. */
    @Volatile public var middleCalibration: FlexCalibration = FlexCalibration.MIDDLE_DEFAULT

    /** Whose hand the wearer shakes; [NoPartner] is an open hand. */
    @Volatile public var partner: PartnerHand = NoPartner

    /** Whether a LucidGloves glove gets force-feedback commands; turning it off does not release by itself ([releaseForceFeedback]). */
    @Volatile public var forceFeedbackOn: Boolean = true

    /** Where the wearer's pose goes, or null to send it nowhere. */
    @Volatile public var poseSink: HandPoseSink? = null

    /** The wearer's thumb angle at the last sample (0 on a fault). */
    public var selfThumbDegrees: Double = 0.0
        private set

    /** The wearer's middle-finger angle at the last sample (0 on a fault). */
    public var selfMiddleDegrees: Double = 0.0
        private set

    /** Whether the thumb's last reading was a fault (shorted, open, not a number). */
    public var thumbFault: Boolean = false
        private set

    /** Whether the middle finger's last reading was a fault. */
    public var middleFault: Boolean = false
        private set

    /** Whether the handshake was active at the last sample. */
    public var active: Boolean = false
        private set

    /** Samples taken so far. */
    public var samples: Long = 0
        private set

    /** The partner's thumb angle at the last sample. */
    public val partnerThumbDegrees: Double get() = partnerAngles[0]

    /** The partner's middle-finger angle at the last sample. */
    public val partnerMiddleDegrees: Double get() = partnerAngles[1]

    /** [region]'s interaction pressure at the last sample, volts (0 outside a handshake). */
    public fun pressureVolts(region: HandRegion): Double = pressures[region.ordinal]

    /** [region]'s vibration amplitude at the last sample, 0..255. */
    public fun amplitude(region: HandRegion): Int = amplitudes[region.ordinal]

    /** Force-feedback commands sent so far. */
    public val forceFeedbackCommands: Long get() = feedback.commands

    /** A copy of the servo values last sent, thumb … pinky. */
    public fun servoValues(): IntArray = feedback.lastSentValues()

    /**
     * Takes one glove sample (the thumb's and middle finger's divider volts) at [nowNanos]: updates the angles,
     * the handshake and the pressures, sends force feedback and the wearer's pose as due, and returns the phone
     * vibrator's amplitude (the largest region amplitude; 0 outside a handshake).
     */
    public fun onSample(thumbVolts: Double, middleVolts: Double, nowNanos: Long): Int {
        val thumb = divider.resistanceOrNaN(thumbVolts)
        val middle = divider.resistanceOrNaN(middleVolts)
        // A faulty finger counts as open (0°): that releases the partner's actuators.
        thumbFault = thumb.isNaN()
        middleFault = middle.isNaN()
        selfThumbDegrees = if (thumbFault) 0.0 else thumbCalibration.angleOf(thumb)
        selfMiddleDegrees = if (middleFault) 0.0 else middleCalibration.angleOf(middle)
        partner.readAngles(nowNanos, partnerAngles)
        active = session.computeInto(
            selfThumbDegrees, selfMiddleDegrees, partnerAngles[0], partnerAngles[1],
            pressures, actuatorAngles, servos, amplitudes,
        )
        samples++
        if (forceFeedbackOn) feedback.update(servos, nowNanos, forceFeedback)
        val sink = poseSink
        if (sink != null && nowNanos - lastPoseSentNanos >= poseIntervalNanos) {
            sink.send(selfThumbDegrees, selfMiddleDegrees)
            lastPoseSentNanos = nowNanos
        }
        if (!active) return 0
        var phone = 0
        for (a in amplitudes) if (a > phone) phone = a
        return phone
    }

    /** Releases every finger of the glove now (force feedback off, the screen closing); nothing if already released. */
    public fun releaseForceFeedback(nowNanos: Long) {
        feedback.release(nowNanos, forceFeedback)
    }

    public companion object {
        /** The wearer's pose goes out at most 30 times a second: smooth enough for a grip, light enough for a phone's uplink. */
        public const val POSE_INTERVAL_NANOS: Long = 33_000_000L
    }
}
