package org.hapticon.app.sensors

import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.map
import org.hapticon.sensor.grains.FirmwareCommands
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.live.CommandHandle
import org.hapticon.sensor.live.SessionState
import org.hapticon.sensor.live.OutgoingCommand
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.FramedEncoder

/**
 * [StimulatorLink] over the live serial session: SET_GRAINS (a setting) and STIMULATE (an event) built by
 * [FirmwareCommands] and queued through [SensorSession.submit] while a board streams the framed protocol (the only one
 * with those commands), each followed to the board's ack; the force range is the one the board's device info announced.
 */
class SessionStimulatorLink(private val session: SensorSession) : StimulatorLink {
    // One encoder for this link's commands, so its sequence numbers run on (FramedEncoder: one per direction).
    private val encoder = FramedEncoder()

    override val ready: Flow<Boolean> = session.state.map(::isFramedStream)

    override fun isReady(): Boolean = isFramedStream(session.state.value)

    override fun forceRange(): FirmwareForceRange? = if (isReady()) FirmwareForceRange.fromStream(session.currentInfo()) else null

    override fun send(params: FirmwareGrainParams): CommandHandle? = submit { FirmwareCommands.setGrains(encoder, params) }

    override fun stimulate(stimulus: FirmwareStimulus): CommandHandle? = submit { FirmwareCommands.stimulate(encoder, stimulus) }

    private fun submit(build: () -> OutgoingCommand): CommandHandle? {
        if (!isReady()) return null
        // Built and queued under one lock, so the board sees this link's sequence numbers in queue order.
        return synchronized(encoder) { session.submit(build()) }
    }

    private fun isFramedStream(state: SessionState): Boolean = state is SessionState.Streaming && state.protocol == SensorProtocol.FRAMED
}
