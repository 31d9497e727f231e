package org.hapticon.app.feature.sensors

import org.hapticon.app.sensors.StimulatorLink
import kotlinx.coroutines.flow.MutableStateFlow
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.live.CommandHandle
import org.hapticon.sensor.live.CommandState

/**
 * A stimulator link that keeps what it was sent; [ready] stands for a framed board streaming, [range] for the force
 * range its device info announced (a 10-bit raw channel unless a test says otherwise). Each command's handle is kept in
 * [handles], so a test can play the board's answer ([TestCommandHandle.answer]).
 */
class TestStimulatorLink(ready: Boolean, var range: FirmwareForceRange? = FirmwareForceRange.ofAdcBits(10)) : StimulatorLink {
    override val ready = MutableStateFlow(ready)

    /** What reached the "board", in order. */
    val sent = ArrayList<FirmwareGrainParams>()

    /** The calibration stimuli that reached the "board", in order. */
    val stimuli = ArrayList<FirmwareStimulus>()

    /** The handles of every command queued, in order. */
    val handles = ArrayList<TestCommandHandle>()

    override fun isReady(): Boolean = ready.value

    override fun forceRange(): FirmwareForceRange? = if (ready.value) range else null

    override fun send(params: FirmwareGrainParams): CommandHandle? {
        if (!ready.value) return null
        sent += params
        return TestCommandHandle("the grain settings (${params.grainCount} grains on ${params.pattern.activeCount} electrodes)").also { handles += it }
    }

    override fun stimulate(stimulus: FirmwareStimulus): CommandHandle? {
        if (!ready.value) return null
        stimuli += stimulus
        return TestCommandHandle("the ${stimulus.durationMillis} ms stimulus on electrode ${stimulus.electrode + 1}").also { handles += it }
    }
}

/** A command "written" to the test board, awaiting the answer the test gives with [answer]. */
class TestCommandHandle(override val description: String) : CommandHandle {
    override val state = MutableStateFlow<CommandState>(CommandState.Sent(isFinal = false))

    /** The board's answer (or its silence: [CommandState.TimedOut]). */
    fun answer(outcome: CommandState) {
        state.value = outcome
    }
}
