package org.hapticon.sensor.port

import java.io.Closeable
import java.io.IOException

/**
 * A byte pipe to a sensor or actuator board: a USB serial chip on the phone, a fake in tests, a
 * recorded file on the command line. Everything above this interface is plain Kotlin.
 *
 * Implementations are not thread-safe for concurrent reads; one reader and one writer thread may
 * use a port at the same time. [close] may be called from any thread and unblocks a pending [read],
 * which then throws or returns -1; only finite sources (recordings) return -1 otherwise.
 */
public interface SerialPort : Closeable {
    /**
     * Applies line settings (ignored by transports without a line, such as files).
     * @throws UnsupportedSettingException if the device cannot do them (e.g. a baud rate its clock can't divide to).
     * @throws IOException if the device rejects them or is gone.
     */
    public fun configure(settings: LineSettings)

    /**
     * Reads available bytes into [buffer] from [offset], waiting at most [timeoutMillis]
     * (0 waits for ever). Returns the number of bytes read, 0 on timeout, or -1 at the end of a
     * finite source (a recording). Does not allocate.
     * @throws PortDisconnectedException when the device was unplugged.
     * @throws IOException for other transfer errors.
     */
    public fun read(buffer: ByteArray, offset: Int = 0, length: Int = buffer.size - offset, timeoutMillis: Int = 0): Int

    /**
     * Writes all [length] bytes from [offset] within [timeoutMillis] in total (one deadline across
     * chunks; 0 means no deadline, as for [read]).
     * @throws PortTimeoutException if the deadline passes before every byte is written.
     * @throws PortDisconnectedException when the device was unplugged.
     */
    public fun write(buffer: ByteArray, offset: Int = 0, length: Int = buffer.size - offset, timeoutMillis: Int)

    /** Whether the port is open: false after [close] or a disconnect. */
    public val isOpen: Boolean
}

/**
 * Serial line settings. Many boards (Arduino Leonardo, Teensy, RP2040 and ESP32-S2/S3 native USB)
 * send nothing until the host asserts DTR, so both control lines are asserted by default.
 */
public data class LineSettings(
    val baudRate: Int = 115_200,
    val dataBits: Int = 8,
    val parity: Parity = Parity.NONE,
    val stopBits: StopBits = StopBits.ONE,
    val dtr: Boolean = true,
    val rts: Boolean = true,
) {
    init {
        require(baudRate in 300..12_000_000) { "baudRate must be in 300..12000000, was $baudRate" }
        require(dataBits in 5..8) { "dataBits must be in 5..8, was $dataBits" }
    }
}

/** Parity bit setting. */
public enum class Parity { NONE, ODD, EVEN, MARK, SPACE }

/** Stop bits setting. */
public enum class StopBits { ONE, ONE_POINT_FIVE, TWO }

/** The device behind a port is gone (unplugged, powered off). */
public class PortDisconnectedException(message: String) : IOException(message)

/** The port cannot apply a requested line setting. */
public class UnsupportedSettingException(message: String) : IOException(message)

/** A write did not finish before its deadline. */
public class PortTimeoutException(message: String) : IOException(message)
