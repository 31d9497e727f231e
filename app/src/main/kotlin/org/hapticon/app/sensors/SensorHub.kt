package org.hapticon.app.sensors

import java.io.Closeable
import java.io.IOException
import java.util.concurrent.CopyOnWriteArrayList
import java.util.concurrent.Executor
import java.util.concurrent.Executors
import java.util.concurrent.atomic.AtomicLong
import java.util.concurrent.atomic.AtomicReference
import kotlinx.coroutines.CancellationException
import kotlinx.coroutines.Dispatchers
import kotlinx.coroutines.withContext
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.SensorReader
import org.hapticon.sensor.port.SerialPort
import org.hapticon.sensor.protocol.FrameError
import org.hapticon.sensor.protocol.StreamDecoder
import org.hapticon.sensor.protocol.StreamStats

/** Where the connection to a board is. */
sealed interface ConnectionState {
    /** Nothing connected yet. */
    data object Idle : ConnectionState

    /** The system's USB permission dialog is up. */
    data class RequestingPermission(val device: SensorDevice) : ConnectionState

    /** Opening the port and configuring the chip. */
    data class Opening(val device: SensorDevice) : ConnectionState

    /** Reading and decoding. */
    data class Streaming(val device: SensorDevice, val protocol: SensorProtocol, val baudRate: Int) : ConnectionState

    /** The stream stopped; everything decoded until then is kept. */
    data class Stopped(val device: SensorDevice, val protocol: SensorProtocol, val cause: StopCause, val message: String? = null) :
        ConnectionState

    /** The user refused USB access. */
    data class PermissionDenied(val device: SensorDevice) : ConnectionState

    /** The board could not be opened. */
    data class Failed(val device: SensorDevice, val message: String) : ConnectionState
}

/** Why a stream stopped. */
enum class StopCause {
    /** The board was unplugged (or reset) mid-stream. */
    UNPLUGGED,

    /** A finite source (a recording) ended. */
    ENDED,

    /** A read failed. */
    FAILED,

    /** The user disconnected. */
    BY_USER,
}

/** The decoder's counters, copied for the UI. */
data class StreamCounters(
    val bytes: Long = 0,
    val frames: Long = 0,
    val badFrames: Long = 0,
    val droppedBytes: Long = 0,
    val ignoredLines: Long = 0,
    val sequenceGaps: Long = 0,
    val lostFrames: Long = 0,
    /** Frames cut short by the end of the stream (an unplug mid-frame). */
    val truncatedFrames: Long = 0,
)

/** What the stream holds now, copied for the UI. */
data class StreamSnapshot(
    val info: StreamInfo?,
    /** The newest value of each channel. */
    val latest: List<Double>,
    val counters: StreamCounters,
    /** Samples received since connecting; changes whenever the plots have something new. */
    val samples: Long,
    /** Frames per second over the last second, or null before a second has passed. */
    val measuredRateHz: Double?,
)

/**
 * The one live connection to a sensor board: opens it through [usb], reads it on a thread of its
 * own with sensor-bridge's [SensorReader], decodes it with the chosen [SensorProtocol], keeps the
 * newest values, a plot [history] and the decoder's counters, and hands every frame to the
 * registered [FrameListener]s (FSR grains, glove) on the reading thread.
 *
 * When the stream stops (unplug, end, failure, [disconnect]) everything decoded so far stays until
 * the next [connect]. Per frame nothing is allocated here; the UI copies a [snapshot] at its own rate.
 *
 * Commands to the board ([send], e.g. force feedback) are written by [writer], off both the main
 * thread and the reading thread, so a stalled USB write can neither freeze the UI nor stop the stream.
 */
class SensorHub(
    private val usb: UsbDevices,
    private val clock: () -> Long = System::nanoTime,
    val history: ChannelHistory = ChannelHistory(),
    private val writer: Executor = defaultWriter(),
) {
    private val connection = MutableStateFlow<ConnectionState>(ConnectionState.Idle)
    private val listeners = CopyOnWriteArrayList<FrameListener>()
    private val lock = Any()

    // Guarded by lock: written on the reading thread, read by snapshot().
    private val latest = DoubleArray(LiveFrame.MAX_CHANNELS)
    private var latestCount = 0
    private var info: StreamInfo? = null
    private var bytes = 0L
    private var frames = 0L
    private var badFrames = 0L
    private var droppedBytes = 0L
    private var ignoredLines = 0L
    private var sequenceGaps = 0L
    private var lostFrames = 0L
    private var truncated = 0L
    private var rateWindowStart = 0L
    private var rateWindowSamples = 0L
    private var samples = 0L
    private var measuredRate = Double.NaN

    @Volatile private var reader: SensorReader? = null
    @Volatile private var port: SerialPort? = null
    @Volatile private var stopRequested = false
    private val outputError = MutableStateFlow<String?>(null)
    private val pendingCommand = AtomicReference<ByteArray?>(null)
    private val commandsWritten = AtomicLong()
    private val commandsFailed = AtomicLong()
    private val writeFailure = MutableStateFlow<String?>(null)

    /** Where the connection is. */
    val state: StateFlow<ConnectionState> = connection.asStateFlow()

    /** Set when a frame listener failed and was removed (e.g. a safety limit refused its output). */
    val listenerError: StateFlow<String?> = outputError.asStateFlow()

    /** Why the last command to the board could not be written (a timeout, an unplug), or null. */
    val writeError: StateFlow<String?> = writeFailure.asStateFlow()

    /** Commands written to the board since the hub was made. */
    val commandsSent: Long get() = commandsWritten.get()

    /** Commands that could not be written (timeout, unplug, I/O error). */
    val commandsLost: Long get() = commandsFailed.get()

    /**
     * Queues [command] for the board on the line and returns at once: false when no stream is running.
     * Commands are state, not events (servo positions): if one is still waiting to be written, the
     * newer replaces it, so a slow board gets the newest command rather than a growing backlog. Each
     * write has [timeoutMillis]; a failure is counted in [commandsLost] and reported in [writeError].
     */
    fun send(command: ByteArray, timeoutMillis: Int = WRITE_TIMEOUT_MILLIS): Boolean {
        val target = port ?: return false
        if (connection.value !is ConnectionState.Streaming || !target.isOpen) return false
        if (pendingCommand.getAndSet(command) == null) {
            writer.execute { writePending(target, timeoutMillis) }
        }
        return true
    }

    private fun writePending(target: SerialPort, timeoutMillis: Int) {
        val command = pendingCommand.getAndSet(null) ?: return
        try {
            target.write(command, 0, command.size, timeoutMillis)
            commandsWritten.incrementAndGet()
        } catch (e: IOException) {
            // The board may be gone or stalled; the stream's own reader reports an unplug.
            commandsFailed.incrementAndGet()
            writeFailure.value = e.message ?: e.javaClass.simpleName
        }
    }

    /** What the stream has given so far. */
    fun snapshot(): StreamSnapshot = synchronized(lock) {
        StreamSnapshot(
            info = info,
            latest = List(latestCount) { latest[it] },
            counters = StreamCounters(bytes, frames, badFrames, droppedBytes, ignoredLines, sequenceGaps, lostFrames, truncated),
            samples = samples,
            measuredRateHz = measuredRate.takeUnless { it.isNaN() },
        )
    }

    /** The stream's channel names and units, once known. */
    fun currentInfo(): StreamInfo? = synchronized(lock) { info }

    /** Calls [listener] with every frame from now on, on the reading thread; close the handle to stop. */
    fun addFrameListener(listener: FrameListener): Closeable {
        listeners += listener
        return Closeable { listeners -= listener }
    }

    /**
     * Connects to [device]: asks for permission, opens it at [baudRate] and starts reading [protocol].
     * A stream already running is stopped first. Returns when the stream runs or failed to start;
     * [state] tells which.
     */
    suspend fun connect(device: SensorDevice, protocol: SensorProtocol, baudRate: Int) {
        if (reader?.isRunning == true) {
            disconnect()
            withContext(Dispatchers.IO) { awaitStopped(STOP_WAIT_MILLIS) }
        }
        resetData()
        outputError.value = null
        writeFailure.value = null
        connection.value = ConnectionState.RequestingPermission(device)
        val opened = try {
            if (!usb.requestPermission(device)) {
                connection.value = ConnectionState.PermissionDenied(device)
                return
            }
            connection.value = ConnectionState.Opening(device)
            usb.open(device, LineSettings(baudRate = baudRate))
        } catch (e: UsbAccessDeniedException) {
            connection.value = ConnectionState.PermissionDenied(device)
            return
        } catch (e: CancellationException) {
            connection.value = ConnectionState.Idle
            throw e
        } catch (e: IOException) {
            connection.value = ConnectionState.Failed(device, e.message ?: e.javaClass.simpleName)
            return
        }
        start(opened, device, protocol, baudRate)
    }

    /**
     * Reads [port] with [protocol] as if it had been opened for [device]; for recordings and tests.
     */
    fun start(port: SerialPort, device: SensorDevice, protocol: SensorProtocol, baudRate: Int) {
        stopRequested = false
        val adapter = ProtocolAdapter(protocol, ::onFrame)
        val decoder = CountingDecoder(adapter)
        val newReader = SensorReader(port, decoder, { reason, cause -> onStopped(port, device, protocol, reason, cause) })
        this.port = port
        reader = newReader
        connection.value = ConnectionState.Streaming(device, protocol, baudRate)
        newReader.start("hapticon-sensor-reader")
    }

    /** Stops reading and closes the port; what was decoded stays. Harmless when nothing runs. */
    fun disconnect() {
        val running = reader ?: return
        stopRequested = true
        running.stop()
        // Closing wakes a read blocked in a transfer; the reader then reports and ends.
        runCatching { port?.close() }
    }

    /** Waits at most [timeoutMillis] for the reading thread to end; true if it has (or never ran). */
    fun awaitStopped(timeoutMillis: Long): Boolean = reader?.awaitStop(timeoutMillis) ?: true

    private fun resetData() {
        synchronized(lock) {
            latestCount = 0
            info = null
            bytes = 0; frames = 0; badFrames = 0; droppedBytes = 0; ignoredLines = 0
            sequenceGaps = 0; lostFrames = 0; truncated = 0
            rateWindowStart = 0; rateWindowSamples = 0; samples = 0; measuredRate = Double.NaN
        }
        history.clear()
    }

    private fun onFrame(frame: LiveFrame, frameInfo: StreamInfo) {
        synchronized(lock) {
            val n = frame.channelCount
            frame.values.copyInto(latest, 0, 0, n)
            latestCount = n
            if (info !== frameInfo) info = frameInfo
            samples++
            val now = frame.receivedNanos
            if (rateWindowStart == 0L) {
                rateWindowStart = now
                rateWindowSamples = samples
            } else if (now - rateWindowStart >= RATE_WINDOW_NANOS) {
                measuredRate = (samples - rateWindowSamples) * 1e9 / (now - rateWindowStart)
                rateWindowStart = now
                rateWindowSamples = samples
            }
        }
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

    private fun copyStats(stats: StreamStats) {
        synchronized(lock) {
            bytes = stats.bytes
            frames = stats.frames
            badFrames = stats.badFrames
            droppedBytes = stats.droppedBytes
            ignoredLines = stats.ignoredLines
            sequenceGaps = stats.sequenceGaps
            lostFrames = stats.lostFrames
            truncated = stats.badFrames(FrameError.TRUNCATED)
        }
    }

    private fun publishInfo(streamInfo: StreamInfo) {
        synchronized(lock) {
            // Device info may arrive before any sample: show it at once.
            if (info !== streamInfo && (streamInfo.channelCount > 0 || streamInfo.deviceDescription != null)) info = streamInfo
        }
    }

    private fun onStopped(stoppedPort: SerialPort, device: SensorDevice, protocol: SensorProtocol, reason: SensorReader.StopReason, cause: Throwable?) {
        runCatching { stoppedPort.close() }
        val stopCause = when {
            stopRequested -> StopCause.BY_USER
            reason == SensorReader.StopReason.DISCONNECTED -> StopCause.UNPLUGGED
            reason == SensorReader.StopReason.END_OF_STREAM -> StopCause.ENDED
            reason == SensorReader.StopReason.STOPPED -> StopCause.BY_USER
            else -> StopCause.FAILED
        }
        val message = if (stopCause == StopCause.FAILED) cause?.message ?: cause?.javaClass?.simpleName else null
        connection.value = ConnectionState.Stopped(device, protocol, stopCause, message)
    }

    /** Copies the decoder's counters after every read, so bad frames show even when no good one follows. */
    private inner class CountingDecoder(private val adapter: ProtocolAdapter) : StreamDecoder {
        private val inner = adapter.decoder
        override val stats: StreamStats get() = inner.stats

        override fun feed(bytes: ByteArray, offset: Int, length: Int) {
            adapter.nowNanos = clock()
            inner.feed(bytes, offset, length)
            publishInfo(adapter.info)
            copyStats(inner.stats)
        }

        override fun finish() {
            inner.finish()
            copyStats(inner.stats)
        }
    }

    private companion object {
        const val STOP_WAIT_MILLIS = 1_000L
        const val RATE_WINDOW_NANOS = 1_000_000_000L

        /** Long enough for a 26-byte command at 9600 baud plus a busy board; short enough not to pile up. */
        const val WRITE_TIMEOUT_MILLIS = 100

        fun defaultWriter(): Executor = Executors.newSingleThreadExecutor { task ->
            Thread(task, "hapticon-sensor-writer").apply { isDaemon = true }
        }
    }
}
