package org.hapticon.app.sensors

import kotlinx.coroutines.flow.Flow
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.live.CommandHandle

/**
 * The board's stimulator, which renders compliance grains stand-alone from a SET_GRAINS command ([FirmwareGrainParams])
 * and gives single calibration stimuli from a STIMULATE command ([FirmwareStimulus]). [ready] says whether a board that
 * takes them (framed protocol) is streaming; [send] and [stimulate] queue a command and return its handle, whose state
 * follows it to the board's ack or NACK, or null when nothing could be queued.
 */
interface StimulatorLink {
    /** True while a framed board is streaming. */
    val ready: Flow<Boolean>

    /** Whether a framed board is streaming now. */
    fun isReady(): Boolean

    /**
     * The range the board bins its force channel over: its ADC's full scale from its device info
     * ([FirmwareForceRange.fromStream]); null when no framed board streams or its force channel is not in raw counts.
     */
    fun forceRange(): FirmwareForceRange?

    /** Queues [params] for the board (a newer set replaces one still waiting); null when no framed board is streaming. */
    fun send(params: FirmwareGrainParams): CommandHandle?

    /** Queues one calibration [stimulus] for the board (never replaced); null when no framed board is streaming. */
    fun stimulate(stimulus: FirmwareStimulus): CommandHandle?

    companion object {
        /** Why nothing was sent: no framed board. */
        const val NO_BOARD: String = "Connect a board with the Framed protocol first"

        /** Why nothing was sent: the board's force channel has no announced range. */
        const val NO_FORCE_RANGE: String = "The board's force channel (ch0) is not in raw ADC counts, so its range is unknown: nothing was sent"
    }
}
