package org.hapticon.sensor.live

import java.io.Closeable
import java.io.IOException
import java.util.concurrent.CopyOnWriteArrayList
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import kotlinx.coroutines.withContext
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SensorReader
import org.hapticon.sensor.port.SerialPort
import org.hapticon.sensor.protocol.SensorProtocol
import org.hapticon.sensor.protocol.stream.StreamDecoder
import org.hapticon.sensor.protocol.stream.StreamStats
import org.hapticon.sensor.protocol.LiveFrame
import org.hapticon.sensor.protocol.StreamInfo
import org.hapticon.sensor.protocol.FrameListener

/** Where the connection to a board is. */
public sealed interface SessionState {
    /** Nothing connected yet. */
    public data object Idle : SessionState

    /** The system's USB permission dialog is up. */
    public data class RequestingPermission(val device: SensorDevice) : SessionState

    /** Opening the port and configuring the chip. */
    public data class Opening(val device: SensorDevice) : SessionState

    /** Reading and decoding. */
    public data class Streaming(val device: SensorDevice, val protocol: SensorProtocol, val baudRate: Int) : SessionState

    /** The stream stopped; everything decoded until then is kept. */
    public data class Stopped(val device: SensorDevice, val protocol: SensorProtocol, val cause: StopCause, val message: String? = null) :
        SessionState

    /** The user refused USB access. */
    public data class PermissionDenied(val device: SensorDevice) : SessionState

    /** The board could not be opened. */
    public data class Failed(val device: SensorDevice, val message: String) : SessionState
}

/** Why a stream stopped. */
public enum class StopCause {
    /** The board was unplugged (or reset) mid-stream. */
    UNPLUGGED,

    /** A finite source (a recording) ended. */
    ENDED,

    /** A read failed. */
    FAILED,

    /** The user disconnected. */
    BY_USER,
}

/**
 * The one live connection to a sensor board, as a state machine over [SessionState]: opens it
 * through [usb], reads it on a thread of its own with [SensorReader], decodes it with the chosen
 * [SensorProtocol] ([LiveDecoder] over [SensorProtocol.decoder]), and hands every
 * frame to the registered [FrameListener]s (FSR grains, glove) on the reading thread. The newest
 * values, counters and rate are kept by a [StreamTally] (copied by [snapshot]), the plot points by
 * [history]; commands to the board go through [commands] ([CommandWriter]: settings coalesce per key, events
 * queue in order), and the board's acks (framed protocol) settle them: each [submit] returns a [CommandHandle]
 * whose state ends acknowledged, rejected with the board's reason, or timed out; [commandError] says the last
 * problem in one line and the [snapshot]'s counters count them.
 *
 * When the stream stops (unplug, end, failure, [disconnect]) everything decoded so far stays until
 * the next [connect]. Per frame nothing is allocated here; the UI copies a [snapshot] at its own rate.
 *
 * [readerThreadSetup] runs first on each stream's reading thread ([SensorReader]'s `threadSetup`), before its
 * first read: the app raises that thread to urgent-audio priority there, since the grains are decided on it.
 */
public class SensorSession(
    private val usb: UsbDevices,
    private val clock: () -> Long = System::nanoTime,
    public val history: ChannelHistory = ChannelHistory(),
    private val commands: CommandWriter = CommandWriter(),
    private val readerThreadSetup: () -> Unit = {},
) {
    private val connection = MutableStateFlow<SessionState>(SessionState.Idle)
    private val listeners = CopyOnWriteArrayList<FrameListener>()
    private val tally = StreamTally()

    @Volatile private var reader: SensorReader? = null
    @Volatile private var port: SerialPort? = null
    @Volatile private var stopRequested = false
    private val outputError = MutableStateFlow<String?>(null)

    /** Where the connection is. */
    public val state: StateFlow<SessionState> = connection.asStateFlow()

    /** Set when a frame listener failed and was removed (e.g. a safety limit refused its output). */
    public val listenerError: StateFlow<String?> = outputError.asStateFlow()

    /** Why the last command to the board could not be written (a timeout, an unplug), or null. */
    public val writeError: StateFlow<String?> get() = commands.writeError

    /**
     * The last command that went wrong, in one line (the board refused it and why, no answer came, the queue was
     * full, or it could not be written); null since the stream started until one does.
     */
    public val commandError: StateFlow<String?> get() = commands.commandError

    /** Commands written to the board since the stream started. */
    public val commandsSent: Long get() = commands.commandsSent

    /** Commands that could not be written (timeout, unplug, I/O error) since the stream started. */
    public val commandsLost: Long get() = commands.commandsLost

    /**
     * Queues raw [command] bytes for the board on the line and returns at once: false when no stream is running.
     * They form one setting: a command still waiting is replaced by the newer one ([CommandWriter.send]); no ack
     * is awaited (for the LucidGloves force feedback). Each write has [timeoutMillis].
     */
    public fun send(command: ByteArray, timeoutMillis: Int = CommandWriter.WRITE_TIMEOUT_MILLIS): Boolean {
        val target = streamingPort() ?: return false
        commands.send(target, command, timeoutMillis)
        return true
    }

    /**
     * Queues [command] for the board ([CommandWriter.submit]: an event in order, a setting replacing a waiting one
     * of its key) and returns its handle at once, or null when no stream is running. The handle's state follows the
     * command to the board's answer; a full queue refuses an event at once ([CommandState.Overflowed]).
     */
    public fun submit(command: OutgoingCommand, timeoutMillis: Int = CommandWriter.WRITE_TIMEOUT_MILLIS): CommandHandle? {
        val target = streamingPort() ?: return null
        return commands.submit(target, command, timeoutMillis)
    }

    private fun streamingPort(): SerialPort? {
        val target = port ?: return null
        if (connection.value !is SessionState.Streaming || !target.isOpen) return null
        return target
    }

    /** What the stream has given so far, with the commands' counts; overdue acks are timed out first. */
    public fun snapshot(): StreamSnapshot {
        commands.expireOverdue()
        return tally.snapshot(commands.counts())
    }

    /** The stream's channel names and units, once known. */
    public fun currentInfo(): StreamInfo? = tally.currentInfo()

    /** Calls [listener] with every frame from now on, on the reading thread; close the handle to stop. */
    public fun addFrameListener(listener: FrameListener): Closeable {
        listeners += listener
        return Closeable { listeners -= listener }
    }

    /**
     * Connects to [device]: asks for permission, opens it at [baudRate] and starts reading [protocol].
     * A stream already running is stopped first. Returns when the stream runs or failed to start;
     * [state] tells which.
     */
    public suspend fun connect(device: SensorDevice, protocol: SensorProtocol, baudRate: Int) {
        if (reader?.isRunning == true) {
            disconnect()
            withContext(Dispatchers.IO) { awaitStopped(STOP_WAIT_MILLIS) }
        }
        resetData()
        outputError.value = null
        commands.clearError()
        connection.value = SessionState.RequestingPermission(device)
        val opened = try {
            if (!usb.requestPermission(device)) {
                connection.value = SessionState.PermissionDenied(device)
                return
            }
            connection.value = SessionState.Opening(device)
            usb.open(device, LineSettings(baudRate = baudRate))
        } catch (e: UsbAccessDeniedException) {
            connection.value = SessionState.PermissionDenied(device)
            return
        } catch (e: CancellationException) {
            connection.value = SessionState.Idle
            throw e
        } catch (e: IOException) {
            connection.value = SessionState.Failed(device, e.message ?: e.javaClass.simpleName)
            return
        }
        start(opened, device, protocol, baudRate)
    }

    /**
     * Reads [port] with [protocol] as if it had been opened for [device]; for recordings and tests.
     */
    public fun start(port: SerialPort, device: SensorDevice, protocol: SensorProtocol, baudRate: Int) {
        stopRequested = false
        commands.reset()
        val decoder = CountingDecoder(LiveDecoder(protocol, commands::onAck, ::onFrame))
        val newReader = SensorReader(port, decoder, { reason, cause -> onStopped(port, device, protocol, reason, cause) }, threadSetup = readerThreadSetup)
        this.port = port
        reader = newReader
        connection.value = SessionState.Streaming(device, protocol, baudRate)
        newReader.start("hapticon-sensor-reader")
    }

    /** Stops reading and closes the port; what was decoded stays. Harmless when nothing runs. */
    public fun disconnect() {
        val running = reader ?: return
        stopRequested = true
        running.stop()
        // Closing wakes a read blocked in a transfer; the reader then reports and ends.
        runCatching { port?.close() }
    }

    /** Waits at most [timeoutMillis] for the reading thread to end; true if it has (or never ran). */
    public fun awaitStopped(timeoutMillis: Long): Boolean = reader?.awaitStop(timeoutMillis) ?: true

    private fun resetData() {
        tally.reset()
        history.clear()
    }

    private fun onFrame(frame: LiveFrame, frameInfo: StreamInfo) {
        tally.onFrame(frame, frameInfo)
        history.append(frame)
        for (listener in listeners) {
            try {
                listener.onFrame(frame, frameInfo)
            } catch (e: RuntimeException) {
                // A failing output must not end the stream, and must not run again.
                listeners -= listener
                outputError.value = e.message ?: e.javaClass.simpleName
            }
        }
    }

    private fun onStopped(stoppedPort: SerialPort, device: SensorDevice, protocol: SensorProtocol, reason: SensorReader.StopReason, cause: Throwable?) {
        runCatching { stoppedPort.close() }
        commands.abandonAwaiting("the stream stopped before the board answered")
        val stopCause = when {
            stopRequested -> StopCause.BY_USER
            reason == SensorReader.StopReason.DISCONNECTED -> StopCause.UNPLUGGED
            reason == SensorReader.StopReason.END_OF_STREAM -> StopCause.ENDED
            reason == SensorReader.StopReason.STOPPED -> StopCause.BY_USER
            else -> StopCause.FAILED
        }
        val message = if (stopCause == StopCause.FAILED) cause?.message ?: cause?.javaClass?.simpleName else null
        connection.value = SessionState.Stopped(device, protocol, stopCause, message)
    }

    /** Copies the decoder's counters after every read, so bad frames show even when no good one follows. */
    private inner class CountingDecoder(private val live: LiveDecoder) : StreamDecoder {
        private val inner = live.decoder
        override val stats: StreamStats get() = inner.stats

        override fun feed(bytes: ByteArray, offset: Int, length: Int) {
            live.nowNanos = clock()
            inner.feed(bytes, offset, length)
            tally.publishInfo(live.info)
            tally.copyStats(inner.stats)
            // A streaming board sends often, so overdue acks end here; snapshot() covers a silent board.
            commands.expireOverdue()
        }

        override fun finish() {
            inner.finish()
            tally.copyStats(inner.stats)
        }
    }

    private companion object {
        const val STOP_WAIT_MILLIS = 1_000L
    }
}
