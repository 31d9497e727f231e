package org.hapticon.sensor.live

import java.io.IOException
import java.util.concurrent.Executor
import java.util.concurrent.Executors
import java.util.concurrent.atomic.AtomicLong
import java.util.concurrent.atomic.AtomicReference
import kotlinx.coroutines.flow.MutableStateFlow
import kotlinx.coroutines.flow.StateFlow
import kotlinx.coroutines.flow.asStateFlow
import org.hapticon.sensor.port.SerialPort

/**
 * Writes commands to a board off both the UI thread and the reading thread, so a stalled USB write can
 * neither freeze the UI nor stop the stream. Commands are state, not events (servo positions): if one
 * is still waiting to be written, a newer one replaces it, so a slow board gets the newest command
 * rather than a growing backlog.
 *
 * @param executor runs the writes; one daemon thread by default (a test may run them inline or hold them).
 */
public class CommandWriter(private val executor: Executor = defaultExecutor()) {
    private val pending = AtomicReference<ByteArray?>(null)
    private val written = AtomicLong()
    private val failed = AtomicLong()
    private val failure = MutableStateFlow<String?>(null)

    /** Why the last command could not be written (a timeout, an unplug), or null. */
    public val writeError: StateFlow<String?> = failure.asStateFlow()

    /** Commands written since this writer was made. */
    public val commandsSent: Long get() = written.get()

    /** Commands that could not be written (timeout, unplug, I/O error). */
    public val commandsLost: Long get() = failed.get()

    /** Forgets the last write error (a new connection). */
    public fun clearError() {
        failure.value = null
    }

    /**
     * Queues [command] for [port] and returns at once; it is written within [timeoutMillis], or counted
     * in [commandsLost] and reported in [writeError]. Replaces a command not yet written.
     */
    public fun send(port: SerialPort, command: ByteArray, timeoutMillis: Int = WRITE_TIMEOUT_MILLIS) {
        if (pending.getAndSet(command) == null) {
            executor.execute { writePending(port, timeoutMillis) }
        }
    }

    private fun writePending(port: SerialPort, timeoutMillis: Int) {
        val command = pending.getAndSet(null) ?: return
        try {
            port.write(command, 0, command.size, timeoutMillis)
            written.incrementAndGet()
        } catch (e: IOException) {
            // The board may be gone or stalled; the stream's own reader reports an unplug.
            failed.incrementAndGet()
            failure.value = e.message ?: e.javaClass.simpleName
        }
    }

    public companion object {
        /** Long enough for a 26-byte command at 9600 baud plus a busy board; short enough not to pile up. */
        public const val WRITE_TIMEOUT_MILLIS: Int = 100

        private fun defaultExecutor(): Executor = Executors.newSingleThreadExecutor { task ->
            Thread(task, "hapticon-sensor-writer").apply { isDaemon = true }
        }
    }
}
