package org.hapticon.companion.board

import java.io.IOException
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.Parity
import org.hapticon.sensor.port.PortDisconnectedException
import org.hapticon.sensor.port.PortTimeoutException
import org.hapticon.sensor.port.SerialPort
import org.hapticon.sensor.port.StopBits
import org.hapticon.sensor.port.UnsupportedSettingException
import com.fazecast.jSerialComm.SerialPort as CommPort

/**
 * sensor-bridge's [SerialPort] over a desktop serial device (`/dev/ttyACM0`, `/dev/ttyUSB0`, `COM3`,
 * `/dev/cu.usbmodem…`) through jSerialComm, so `hapticon board` drives a board with the same session, encoder and
 * ack logic as the app's USB drivers.
 *
 * jSerialComm's timeouts are set once, at open, to short slices (semi-blocking reads: return as soon as one byte
 * is there or after [SLICE_MILLIS]; blocking writes of at most [SLICE_MILLIS]), and [read] and [write] loop over the
 * slices up to their own deadlines: changing jSerialComm's timeouts per call would race between the reading thread
 * and the writer thread (SerialPort.java, `setComPortTimeouts` applies both). A read of 0 ms waits for ever, as the
 * interface asks, yet still notices [close] within a slice.
 */
class DesktopSerialPort internal constructor(private val port: CommPort) : SerialPort {
    @Volatile private var closed = false

    /** The device path, as `hapticon board ports` lists it. */
    val path: String get() = port.systemPortPath

    override val isOpen: Boolean get() = !closed && port.isOpen

    override fun configure(settings: LineSettings) {
        checkOpen()
        val parity = when (settings.parity) {
            Parity.NONE -> CommPort.NO_PARITY
            Parity.ODD -> CommPort.ODD_PARITY
            Parity.EVEN -> CommPort.EVEN_PARITY
            Parity.MARK -> CommPort.MARK_PARITY
            Parity.SPACE -> CommPort.SPACE_PARITY
        }
        val stopBits = when (settings.stopBits) {
            StopBits.ONE -> CommPort.ONE_STOP_BIT
            StopBits.ONE_POINT_FIVE -> CommPort.ONE_POINT_FIVE_STOP_BITS
            StopBits.TWO -> CommPort.TWO_STOP_BITS
        }
        if (!port.setComPortParameters(settings.baudRate, settings.dataBits, stopBits, parity)) {
            throw UnsupportedSettingException("$path cannot do ${settings.baudRate} baud, ${settings.dataBits} data bits, ${settings.parity}, ${settings.stopBits}")
        }
        // Native-USB boards (Leonardo, Teensy, RP2040) send nothing until DTR is asserted (LineSettings).
        // A pseudo-terminal has no modem lines and refuses these: that is not an error.
        if (settings.dtr) port.setDTR() else port.clearDTR()
        if (settings.rts) port.setRTS() else port.clearRTS()
    }

    override fun read(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int {
        if (offset < 0 || length < 0 || offset > buffer.size - length) throw IndexOutOfBoundsException("range [$offset, $offset + $length) is outside 0..${buffer.size}")
        require(timeoutMillis >= 0) { "timeoutMillis must not be negative, was $timeoutMillis" }
        if (length == 0) return 0
        val deadline = System.nanoTime() + timeoutMillis * 1_000_000L
        while (true) {
            checkOpen()
            // readBytes(buffer, bytesToRead, offset): jSerialComm's order, not the interface's.
            val n = port.readBytes(buffer, length, offset)
            if (n > 0) return n
            if (n < 0) throw gone("read")
            if (timeoutMillis != 0 && System.nanoTime() - deadline >= 0) return 0
        }
    }

    override fun write(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int) {
        if (offset < 0 || length < 0 || offset > buffer.size - length) throw IndexOutOfBoundsException("range [$offset, $offset + $length) is outside 0..${buffer.size}")
        require(timeoutMillis >= 0) { "timeoutMillis must not be negative, was $timeoutMillis" }
        val deadline = System.nanoTime() + timeoutMillis * 1_000_000L
        var written = 0
        while (written < length) {
            checkOpen()
            val n = port.writeBytes(buffer, length - written, offset + written)
            if (n < 0) throw gone("write")
            written += n
            if (written < length && timeoutMillis != 0 && System.nanoTime() - deadline >= 0) {
                throw PortTimeoutException("wrote $written of $length bytes to $path before the $timeoutMillis ms deadline")
            }
        }
    }

    override fun close() {
        closed = true
        port.closePort()
    }

    private fun checkOpen() {
        if (closed) throw IOException("$path is closed")
    }

    /** -1 from jSerialComm: closed by us, or the device went away (unplugged, reset). */
    private fun gone(what: String): IOException =
        if (closed) IOException("$path is closed") else PortDisconnectedException("$path: the board is gone ($what failed, error ${port.lastErrorCode})")

    companion object {
        /** jSerialComm's read and write timeout: how often a waiting read or write looks at its deadline and [close]. */
        const val SLICE_MILLIS: Int = 50

        /**
         * Opens the serial device at [path] (as `hapticon board ports` lists it, or any tty path such as a
         * pseudo-terminal) with [settings].
         * @throws IOException when it does not exist, is busy or refuses [settings].
         */
        fun open(path: String, settings: LineSettings): DesktopSerialPort {
            val commPort = try {
                CommPort.getCommPort(path)
            } catch (e: RuntimeException) {
                // SerialPortInvalidPortException (unchecked) for a name that is no port at all.
                throw IOException("$path is not a serial port: ${e.message}")
            }
            commPort.setComPortTimeouts(CommPort.TIMEOUT_READ_SEMI_BLOCKING or CommPort.TIMEOUT_WRITE_BLOCKING, SLICE_MILLIS, SLICE_MILLIS)
            if (!commPort.openPort()) {
                throw IOException("cannot open $path (error ${commPort.lastErrorCode}: missing, busy, or no permission: on Linux join the dialout group)")
            }
            val port = DesktopSerialPort(commPort)
            try {
                port.configure(settings)
            } catch (e: IOException) {
                port.close()
                throw e
            }
            return port
        }

        /** The serial devices jSerialComm finds now, by path. */
        fun list(): List<PortListing> = CommPort.getCommPorts().map {
            PortListing(
                path = it.systemPortPath,
                vendorId = it.vendorID.takeIf { id -> id > 0 },
                productId = it.productID.takeIf { id -> id > 0 },
                description = it.portDescription.orEmpty().ifBlank { it.descriptivePortName.orEmpty() },
                serialNumber = it.serialNumber?.takeUnless { s -> s.isBlank() || s == "Unknown" },
            )
        }.sortedBy { it.path }
    }
}

/** One serial device as `hapticon board ports` prints it. */
data class PortListing(
    /** What `--port` takes: `/dev/ttyACM0`, `COM3`. */
    val path: String,
    /** The USB vendor id, or null for a port that is not USB. */
    val vendorId: Int?,
    /** The USB product id, or null. */
    val productId: Int?,
    /** The driver's or the board's description ("Arduino Uno", "USB Serial"). */
    val description: String,
    /** The USB serial number, when the board has one. */
    val serialNumber: String?,
) {
    /** One tab-separated line: path, `vvvv:pppp` (or `-`), description, serial number (or `-`). */
    fun line(): String {
        val ids = if (vendorId != null && productId != null) "%04x:%04x".format(vendorId, productId) else "-"
        return listOf(path, ids, description.ifBlank { "-" }, serialNumber ?: "-").joinToString("\t") { it.replace(Regex("[\\t\\r\\n]"), " ") }
    }
}
