package org.hapticon.app.feature.sensors

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.map
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.grains.setGrains
import org.hapticon.sensor.grains.stimulate
import org.hapticon.sensor.live.ConnectionState
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol

/**
 * [StimulatorLink] over the live serial session: SET_GRAINS and STIMULATE frames ([FramedEncoder.setGrains],
 * [FramedEncoder.stimulate]) written through [SensorSession.send] while a board streams the framed protocol (the
 * only one with those commands); the force range is the one the board's device info announced.
 */
class HubStimulatorLink(private val hub: SensorSession) : StimulatorLink {
    // One encoder for this link's commands, so its sequence numbers run on (FramedEncoder: one per direction).
    private val encoder = FramedEncoder()

    override val ready: Flow<Boolean> = hub.state.map(::isFramedStream)

    override fun isReady(): Boolean = isFramedStream(hub.state.value)

    override fun forceRange(): FirmwareForceRange? = if (isReady()) FirmwareForceRange.fromStream(hub.currentInfo()) else null

    override fun send(params: FirmwareGrainParams): Boolean = write { buffer -> encoder.setGrains(params, buffer) }

    override fun stimulate(stimulus: FirmwareStimulus): Boolean = write { buffer -> encoder.stimulate(stimulus, buffer) }

    private fun write(encode: (ByteArray) -> Int): Boolean {
        if (!isReady()) return false
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val length = synchronized(encoder) { encode(buffer) }
        return hub.send(buffer.copyOf(length))
    }

    private fun isFramedStream(state: ConnectionState): Boolean = state is ConnectionState.Streaming && state.protocol == SensorProtocol.FRAMED
}
