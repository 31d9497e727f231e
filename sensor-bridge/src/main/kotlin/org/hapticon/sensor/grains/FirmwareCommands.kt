package org.hapticon.sensor.grains

import java.util.Locale
import org.hapticon.sensor.electrotactile.AmplitudeSteps
import org.hapticon.sensor.live.CommandWriter
import org.hapticon.sensor.live.OutgoingCommand
import org.hapticon.sensor.protocol.framed.AckStatus
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol

/**
 * The electrotactile firmware's commands as [OutgoingCommand]s for the [CommandWriter]: SET_GRAINS is a setting
 * (only the newest parameters matter, so a waiting one is replaced), STIMULATE an event (a calibration stimulus
 * happens once and is never dropped). Both carry their amplitude steps, checked again against the 200 steps over
 * 0–2.7 mA when the command is made, and the sequence number the board acknowledges.
 */
public object FirmwareCommands {
    /** The setting key of SET_GRAINS: a newer parameter set replaces one still waiting. */
    public const val SET_GRAINS_KEY: String = "set-grains"

    /**
     * SET_GRAINS with [params], encoded by [encoder] (its next sequence number is the one acknowledged). Call with the
     * encoder held: the sequence number is read right after encoding.
     */
    public fun setGrains(encoder: FramedEncoder, params: FirmwareGrainParams): OutgoingCommand {
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val length = encoder.setGrains(params, buffer)
        return OutgoingCommand(
            bytes = buffer.copyOf(length),
            description = "the grain settings (${params.grainCount} grains on ${params.pattern.activeCount} electrodes)",
            settingKey = SET_GRAINS_KEY,
            ackSequence = encoder.lastSequence,
            stimulationSteps = params.pattern.electrodes().map { params.steps[it] },
            explainNack = ::nackReason,
        )
    }

    /** STIMULATE with [stimulus], encoded by [encoder]: an event, queued in order and never replaced. */
    public fun stimulate(encoder: FramedEncoder, stimulus: FirmwareStimulus): OutgoingCommand {
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val length = encoder.stimulate(stimulus, buffer)
        return OutgoingCommand(
            bytes = buffer.copyOf(length),
            description = String.format(
                Locale.ROOT, "the %d ms stimulus on electrode %d at %.3f mA",
                stimulus.durationMillis, stimulus.electrode + 1, AmplitudeSteps.milliampsOf(stimulus.step),
            ),
            settingKey = null,
            ackSequence = encoder.lastSequence,
            stimulationSteps = listOf(stimulus.step),
            explainNack = ::nackReason,
        )
    }

    /**
     * The firmware's NACK of SET_GRAINS or STIMULATE in words: OUT_OF_RANGE carries grains.h's `ParamError` as
     * its detail (docs/protocols.md "Ack statuses"); other statuses as [CommandWriter.ackReason].
     */
    public fun nackReason(status: AckStatus, detail: Int): String = if (status != AckStatus.OUT_OF_RANGE) {
        CommandWriter.ackReason(status, detail)
    } else {
        when (detail) {
            1 -> "grains outside 0..99"
            2 -> "unknown bin distribution"
            3 -> "bad force range"
            4 -> "fewer than 4 electrodes"
            5 -> "an amplitude step past 200 (2.7 mA)"
            6 -> "filter cutoff not below the Nyquist rate"
            7 -> "grain shorter than its burst"
            8 -> "an electrode past 8"
            9 -> "a stimulus outside 1..1000 ms"
            else -> "a value out of range (detail $detail)"
        }
    }
}
