package org.hapticon.sensor.port

import java.io.IOException
import java.io.OutputStream

/**
 * Wraps a live [SerialPort] and copies every byte read from it to [recording], so a session with a
 * real glove can be saved and replayed later with [ReplayPort]. Everything else passes through.
 * [close] closes the port and then [recording].
 *
 * The copy happens on the reading thread, so give it a buffered stream.
 */
public class RecordingPort(
    private val port: SerialPort,
    private val recording: OutputStream,
) : SerialPort {
    override val isOpen: Boolean get() = port.isOpen

    override fun configure(settings: LineSettings): Unit = port.configure(settings)

    /**
     * Reads from the wrapped port and records what was read.
     * @throws IOException from the port, or if writing the recording fails.
     */
    override fun read(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int {
        val n = port.read(buffer, offset, length, timeoutMillis)
        if (n > 0) recording.write(buffer, offset, n)
        return n
    }

    override fun write(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Unit =
        port.write(buffer, offset, length, timeoutMillis)

    override fun close() {
        try {
            port.close()
        } finally {
            recording.close()
        }
    }
}
