package org.hapticon.companion.board

import java.io.Closeable
import org.hapticon.sensor.grains.FirmwareCommands
import org.hapticon.sensor.grains.FirmwareForceRange
import org.hapticon.sensor.grains.FirmwareGrainParams
import org.hapticon.sensor.grains.FirmwareStimulus
import org.hapticon.sensor.live.CommandHandle
import org.hapticon.sensor.live.CommandState
import org.hapticon.sensor.live.CommandWriter
import org.hapticon.sensor.live.SessionState
import org.hapticon.sensor.live.OutgoingCommand
import org.hapticon.sensor.live.SensorDevice
import org.hapticon.sensor.live.SensorSession
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.live.UsbDevices
import org.hapticon.sensor.live.describeProblem
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SerialPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.framed.FramedEncoder
import org.hapticon.sensor.protocol.framed.FramedProtocol
import kotlinx.coroutines.flow.Flow
import kotlinx.coroutines.flow.flowOf

/**
 * The CLI's link to an electrotactile board: the app's own path, not a second implementation. A [SensorSession]
 * reads [port] with the framed protocol on its reading thread (so acks settle commands as they arrive), one
 * [FramedEncoder] numbers this link's commands (docs/protocols.md: one encoder per board), [FirmwareCommands] builds
 * SET_GRAINS and STIMULATE with their hard limits, and the session's [CommandWriter] writes them and follows each to
 * the board's ack. Each call here waits for that outcome and returns it as a [CommandState].
 *
 * @param port an open port; closed by [close].
 * @param pollMillis how often a wait looks for the ack deadline (the session also checks it on every read).
 */
class BoardLink(
    private val port: SerialPort,
    portName: String,
    baudRate: Int,
    private val writer: CommandWriter = CommandWriter(),
    private val pollMillis: Long = 5,
) : Closeable {
    private val session = SensorSession(NoUsbDevices, commands = writer)
    private val encoder = FramedEncoder()

    init {
        session.start(port, SensorDevice(portName, "desktop serial", 0, 0), SensorProtocol.FRAMED, baudRate)
    }

    /**
     * Asks the board for its device info (REQUEST_INFO) and waits up to [timeoutMillis] for it; null when none came
     * (not a Hapticon framed board, wrong baud rate, or a board still booting).
     */
    fun requestInfo(timeoutMillis: Long = INFO_TIMEOUT_MILLIS): StreamInfo? {
        val buffer = ByteArray(FramedProtocol.MAX_ENCODED_FRAME_LENGTH)
        val length = synchronized(encoder) { encoder.requestInfo(buffer) }
        // REQUEST_INFO is answered with device info, not an ack: a raw write without one awaited.
        session.send(buffer.copyOf(length))
        val deadline = System.nanoTime() + timeoutMillis * 1_000_000
        while (System.nanoTime() - deadline < 0) {
            session.currentInfo()?.takeIf { it.adcBits != null }?.let { return it }
            if (session.state.value !is SessionState.Streaming) return null
            Thread.sleep(pollMillis)
        }
        return session.currentInfo()?.takeIf { it.adcBits != null }
    }

    /** The raw force range the board announced for its grain channel, or null ([FirmwareForceRange.fromStream]). */
    fun forceRange(): FirmwareForceRange? = FirmwareForceRange.fromStream(session.currentInfo())

    /** Sends SET_GRAINS with [params] and waits for the board's answer. */
    fun send(params: FirmwareGrainParams): Outcome = submit { FirmwareCommands.setGrains(encoder, params) }

    /** Sends one calibration STIMULATE and waits for the board's answer. */
    fun stimulate(stimulus: FirmwareStimulus): Outcome = submit { FirmwareCommands.stimulate(encoder, stimulus) }

    private fun submit(build: () -> OutgoingCommand): Outcome {
        // Built and queued under one lock, so the board sees the sequence numbers in queue order (as the app's link).
        val handle: CommandHandle = synchronized(encoder) {
            val command = build()
            session.submit(command) ?: return Outcome(command.description, CommandState.WriteFailed(streamStopped()))
        }
        while (true) {
            val state = handle.state.value
            if (state.isFinal) return Outcome(handle.description, state)
            // A silent board sends nothing that would make the session look at the deadline: look here.
            writer.expireOverdue()
            Thread.sleep(pollMillis)
        }
    }

    private fun streamStopped(): String = when (val s = session.state.value) {
        is SessionState.Stopped -> "the connection stopped (${s.cause.name.lowercase()}${s.message?.let { ": $it" }.orEmpty()})"
        else -> "the board is not connected"
    }

    /** Stops reading and closes the port. */
    override fun close() {
        session.disconnect()
        session.awaitStopped(STOP_WAIT_MILLIS)
        runCatching { port.close() }
    }

    /** What became of one command: [description] in words and its final [state]. */
    data class Outcome(val description: String, val state: CommandState) {
        /** Whether the board applied it. */
        val accepted: Boolean get() = state == CommandState.Acknowledged

        /** One line: `acknowledged: …`, or the problem as the app words it ([describeProblem]). */
        fun line(): String = describeProblem(description, state) ?: "acknowledged: $description"
    }

    /** A session made from an already open port needs no USB host: [SensorSession.start] is given the port. */
    private object NoUsbDevices : UsbDevices {
        override val hasUsbHost: Boolean get() = false
        override val devices: Flow<List<SensorDevice>> = flowOf(emptyList())
        override fun currentDevices(): List<SensorDevice> = emptyList()
        override fun refresh() = Unit
        override suspend fun requestPermission(device: SensorDevice): Boolean = false
        override suspend fun open(device: SensorDevice, settings: LineSettings): SerialPort =
            throw java.io.IOException("the CLI opens its ports itself")
    }

    companion object {
        /** How long [requestInfo] waits: a board that resets when the port opens (Uno, Nano) boots in about 1.5 s. */
        const val INFO_TIMEOUT_MILLIS: Long = 3_000

        private const val STOP_WAIT_MILLIS = 1_000L
    }
}
