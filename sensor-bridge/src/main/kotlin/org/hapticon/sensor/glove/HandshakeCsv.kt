package org.hapticon.sensor.glove

import java.util.Locale

/** One row of a glove angle recording: at [timeSeconds] the thumb was bent [thumbDegrees], the middle finger [middleDegrees]. */
public data class AngleSample(val timeSeconds: Double, val thumbDegrees: Double, val middleDegrees: Double)

/** The commands for the self hand's actuators at [timeSeconds]. */
public data class HandshakeStep(val timeSeconds: Double, val frame: HandshakeFrame)

/**
 * The `hapticon handshake` computation as pure functions: angle recordings in, per-region commands out.
 *
 * Input CSVs have the header `time_s,thumb_deg,middle_deg` and one row per glove sample (times in seconds,
 * strictly increasing; angles in degrees); see [readAngles] for the dialect.
 */
public object HandshakeCsv {
    /** The required header of an angle CSV. */
    public const val ANGLE_HEADER: String = "time_s,thumb_deg,middle_deg"

    /**
     * Parses an angle CSV. Blank lines and `#` comments are skipped; numbers must be finite and times
     * strictly increasing.
     * @throws SensorCsvException naming [source] and the first bad line.
     */
    public fun readAngles(text: String, source: String = "csv"): List<AngleSample> {
        val (_, rows) = readSensorCsv(text, source, listOf(ANGLE_HEADER.split(',')))
        return rows.map { AngleSample(it.values[0], it.values[1], it.values[2]) }
    }

    /**
     * The commands the self hand's actuators get at each of [self]'s time steps, with [session] (a fresh one
     * by default). The partner's angles at a self time are those of its latest sample at or before that time
     * (sample-and-hold, as a receiver over a network would have them); before the partner's first sample its
     * hand counts as open (0°, 0°).
     */
    public fun commands(self: List<AngleSample>, partner: List<AngleSample>, session: HandshakeSession = HandshakeSession()): List<HandshakeStep> {
        var next = 0
        var partnerThumb = 0.0
        var partnerMiddle = 0.0
        return self.map { sample ->
            while (next < partner.size && partner[next].timeSeconds <= sample.timeSeconds) {
                partnerThumb = partner[next].thumbDegrees
                partnerMiddle = partner[next].middleDegrees
                next++
            }
            HandshakeStep(sample.timeSeconds, session.step(sample.thumbDegrees, sample.middleDegrees, partnerThumb, partnerMiddle))
        }
    }

    /**
     * [readAngles] on both texts, then [commands].
     * @throws SensorCsvException naming the file ([selfSource] or [partnerSource]) and line.
     */
    public fun commands(selfCsv: String, partnerCsv: String, selfSource: String = "self", partnerSource: String = "partner"): List<HandshakeStep> =
        commands(readAngles(selfCsv, selfSource), readAngles(partnerCsv, partnerSource))

    /**
     * The steps as CSV: `time_s,active`, then per region `<region>_v,<region>_deg,<region>_servo,<region>_amp`
     * (the palm has no `_servo` column). Pressures with 4 decimals, angles with 2, one line per step, `\n`
     * line ends, locale-independent.
     */
    public fun format(steps: List<HandshakeStep>): String = buildString {
        append("time_s,active")
        for (region in HandRegion.ALL) {
            append(",${region.label}_v,${region.label}_deg")
            if (region.lucidGlovesIndex != null) append(",${region.label}_servo")
            append(",${region.label}_amp")
        }
        append('\n')
        for (step in steps) {
            append(number(step.timeSeconds, 6)).append(',').append(if (step.frame.active) 1 else 0)
            for (command in step.frame.commands) {
                append(',').append(number(command.pressureVolts, 4))
                append(',').append(number(command.actuatorDegrees, 2))
                if (command.servoValue != null) append(',').append(command.servoValue)
                append(',').append(command.vibrationAmplitude)
            }
            append('\n')
        }
    }

    private fun number(value: Double, decimals: Int): String = String.format(Locale.ROOT, "%.${decimals}f", value)
}
