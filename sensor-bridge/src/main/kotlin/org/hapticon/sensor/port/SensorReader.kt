package org.hapticon.sensor.port

import org.hapticon.sensor.protocol.stream.StreamDecoder
import java.io.IOException

/**
 * Reads a [port] in a loop and feeds everything to a [decoder], whose listener then receives the
 * frames on the reading thread. The loop ends when the stream ends, the device is unplugged, a read
 * fails, a listener throws, or [stop] is called; then it calls [StreamDecoder.finish] (frames
 * decoded before are all delivered already; an unfinished one is counted as truncated) and reports
 * once to [listener].
 *
 * Reads wait at most [readTimeoutMillis], so [stop] takes effect within about that long, and
 * nothing here waits for ever: [run] returns when the loop ends, [awaitStop] takes a limit. The port
 * is not closed; it belongs to the caller, who may write commands to it from another thread.
 *
 * Run the loop either on a thread of its own with [start], or on the caller's thread with [run]
 * (the command line, tests). A reader runs once.
 *
 * @param bufferSize bytes asked for per read: small for latency, large for throughput.
 * @param threadSetup runs first on the thread that reads (the reader's own thread with [start], the caller's
 *   with [run]), before the first read: where a platform sets the thread up for its job, e.g. the app raises
 *   it to Android's urgent-audio priority, since this thread decides the vibration grains as an audio
 *   thread renders audio (docs/performance.md). Pure Kotlin here; if it throws, the loop ends at once as
 *   [StopReason.FAILED] with that cause, before any read.
 * @throws IllegalArgumentException if [readTimeoutMillis] or [bufferSize] is not positive.
 */
public class SensorReader(
    private val port: SerialPort,
    private val decoder: StreamDecoder,
    private val listener: Listener,
    private val readTimeoutMillis: Int = DEFAULT_READ_TIMEOUT_MILLIS,
    bufferSize: Int = DEFAULT_BUFFER_SIZE,
    private val threadSetup: () -> Unit = {},
) {
    /** Why the read loop ended. */
    public enum class StopReason {
        /** The port reported the end of a finite source (a recording). */
        END_OF_STREAM,

        /** The device was unplugged ([PortDisconnectedException]). */
        DISCONNECTED,

        /** A read failed with another [IOException], or a frame listener threw. */
        FAILED,

        /** [stop] was called. */
        STOPPED,
    }

    /** Hears when the loop ends. */
    public fun interface Listener {
        /**
         * Called once, on the reading thread, after the last frame: [cause] is the exception behind
         * [StopReason.DISCONNECTED] and [StopReason.FAILED], null otherwise.
         */
        public fun onStopped(reason: StopReason, cause: Throwable?)
    }

    init {
        require(readTimeoutMillis > 0) { "readTimeoutMillis must be positive (0 would wait for ever), was $readTimeoutMillis" }
        require(bufferSize > 0) { "bufferSize must be positive, was $bufferSize" }
    }

    private val buffer = ByteArray(bufferSize)
    private val lock = Object()

    @Volatile private var stopRequested = false
    private var started = false
    private var finished = false

    /**
     * Starts the loop on a new daemon thread named [threadName] and returns at once.
     * @throws IllegalStateException if this reader has already run or been started.
     */
    public fun start(threadName: String = "hapticon-sensor-reader") {
        claim()
        val thread = Thread({ loop() }, threadName)
        thread.isDaemon = true
        thread.start()
    }

    /**
     * Runs the loop on the calling thread until it ends, and returns why (after [listener] heard it).
     * @throws IllegalStateException if this reader has already run or been started.
     */
    public fun run(): StopReason {
        claim()
        return loop()
    }

    /** Asks the loop to end after the current read; returns at once. Harmless if it has ended. */
    public fun stop() {
        stopRequested = true
    }

    /**
     * Waits at most [timeoutMillis] for the loop to end; true if it has ended (or never started).
     * @throws IllegalArgumentException if [timeoutMillis] is negative.
     * @throws InterruptedException if the waiting thread is interrupted.
     */
    public fun awaitStop(timeoutMillis: Long): Boolean {
        require(timeoutMillis >= 0) { "timeoutMillis must not be negative, was $timeoutMillis" }
        val deadline = System.nanoTime() + timeoutMillis * 1_000_000
        synchronized(lock) {
            while (started && !finished) {
                val left = (deadline - System.nanoTime()) / 1_000_000
                if (left <= 0) return false
                lock.wait(left)
            }
            return true
        }
    }

    /** Whether the loop is running. */
    public val isRunning: Boolean get() = synchronized(lock) { started && !finished }

    private fun claim() {
        synchronized(lock) {
            check(!started) { "a SensorReader runs once" }
            started = true
        }
    }

    private fun loop(): StopReason {
        try {
            var reason = StopReason.STOPPED
            var cause: Throwable? = null
            try {
                threadSetup()
                while (!stopRequested) {
                    val n = port.read(buffer, 0, buffer.size, readTimeoutMillis)
                    if (n < 0) {
                        reason = StopReason.END_OF_STREAM
                        break
                    }
                    if (n > 0) decoder.feed(buffer, 0, n)
                }
            } catch (e: PortDisconnectedException) {
                reason = StopReason.DISCONNECTED
                cause = e
            } catch (e: IOException) {
                reason = StopReason.FAILED
                cause = e
            } catch (e: RuntimeException) {
                reason = StopReason.FAILED
                cause = e
            }
            try {
                decoder.finish()
            } catch (e: RuntimeException) {
                // A listener threw while the last frame was delivered; report the first failure only.
                if (cause == null) {
                    reason = StopReason.FAILED
                    cause = e
                }
            }
            listener.onStopped(reason, cause)
            return reason
        } finally {
            synchronized(lock) {
                finished = true
                lock.notifyAll()
            }
        }
    }

    /** Defaults. */
    public companion object {
        /** Default longest wait of one read, which bounds how long [stop] takes. */
        public const val DEFAULT_READ_TIMEOUT_MILLIS: Int = 100

        /** Default read size. */
        public const val DEFAULT_BUFFER_SIZE: Int = 4096
    }
}
