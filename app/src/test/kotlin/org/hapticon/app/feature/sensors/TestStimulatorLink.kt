package org.hapticon.app.feature.sensors

import kotlinx.coroutines.flow.MutableStateFlow
import org.hapticon.sensor.grains.FirmwareGrainParams

/** A stimulator link that keeps what it was sent; [ready] stands for a framed board streaming. */
class TestStimulatorLink(ready: Boolean) : StimulatorLink {
    override val ready = MutableStateFlow(ready)

    /** What reached the "board", in order. */
    val sent = ArrayList<FirmwareGrainParams>()

    override fun send(params: FirmwareGrainParams): Boolean {
        if (!ready.value) return false
        sent += params
        return true
    }
}
