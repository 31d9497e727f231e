package org.hapticon.app.feature.sensors

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.map
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.setGrains
import org.hapticon.sensor.live.ConnectionState
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol

/**
 * [StimulatorLink] over the live serial session: SET_GRAINS frames ([FramedEncoder.setGrains]) written through
 * [SensorSession.send] while a board streams the framed protocol (the only one with that command).
 */
class HubStimulatorLink(private val hub: SensorSession) : StimulatorLink {
    // One encoder for this link's commands, so its sequence numbers run on (FramedEncoder: one per direction).
    private val encoder = FramedEncoder()

    override val ready: Flow<Boolean> = hub.state.map(::isFramedStream)

    override fun send(params: FirmwareGrainParams): Boolean {
        if (!isFramedStream(hub.state.value)) return false
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val length = synchronized(encoder) { encoder.setGrains(params, buffer) }
        return hub.send(buffer.copyOf(length))
    }

    private fun isFramedStream(state: ConnectionState): Boolean = state is ConnectionState.Streaming && state.protocol == SensorProtocol.FRAMED
}
