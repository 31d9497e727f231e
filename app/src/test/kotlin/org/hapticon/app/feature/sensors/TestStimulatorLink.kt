package org.hapticon.app.feature.sensors

import kotlinx.coroutines.flow.MutableStateFlow
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus

/**
 * A stimulator link that keeps what it was sent; [ready] stands for a framed board streaming, [range] for the force
 * range its device info announced (a 10-bit raw channel unless a test says otherwise).
 */
class TestStimulatorLink(ready: Boolean, var range: FirmwareForceRange? = FirmwareForceRange.ofAdcBits(10)) : StimulatorLink {
    override val ready = MutableStateFlow(ready)

    /** What reached the "board", in order. */
    val sent = ArrayList<FirmwareGrainParams>()

    /** The calibration stimuli that reached the "board", in order. */
    val stimuli = ArrayList<FirmwareStimulus>()

    override fun isReady(): Boolean = ready.value

    override fun forceRange(): FirmwareForceRange? = if (ready.value) range else null

    override fun send(params: FirmwareGrainParams): Boolean {
        if (!ready.value) return false
        sent += params
        return true
    }

    override fun stimulate(stimulus: FirmwareStimulus): Boolean {
        if (!ready.value) return false
        stimuli += stimulus
        return true
    }
}
