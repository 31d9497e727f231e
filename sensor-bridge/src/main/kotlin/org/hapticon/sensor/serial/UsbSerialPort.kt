package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.PortDisconnectedException
import org.hapticon.sensor.port.PortTimeoutException
import org.hapticon.sensor.port.SerialPort
import java.io.IOException
import java.util.concurrent.atomic.AtomicBoolean
import kotlin.math.min

/**
 * A serial port on a USB chip. This base class owns what every chip family shares: the open/close
 * life cycle, reads with a timeout, writes chunked by the endpoint's max packet size under one
 * deadline, and telling a read timeout from an unplug. Chip drivers add claiming, initialisation and
 * line settings. Get one from [UsbSerialDriver.openPort].
 *
 * One reader and one writer thread may use the port at once; [close] and [onDeviceDetached] may be
 * called from any thread.
 */
public abstract class UsbSerialPort internal constructor(
    /** The device the port is on. */
    public val device: UsbDeviceDescription,
    /** Which port of the device, 0-based. */
    public val portIndex: Int,
    internal val transport: UsbTransport,
    private val clock: MonotonicClock,
) : SerialPort {
    /** The bulk endpoints the serial data moves on, found while opening. */
    internal class DataEndpoints(val read: UsbEndpointDescription, val write: UsbEndpointDescription)

    private lateinit var endpoints: DataEndpoints
    private lateinit var readBuffer: ByteArray
    private var pendingStart = 0
    private var pendingEnd = 0

    @Volatile private var opened = false

    private val closed = AtomicBoolean(false)

    @Volatile private var disconnected = false

    /** The settings last applied with [configure], or null before the port is open. */
    @Volatile
    public var lineSettings: LineSettings? = null
        private set

    override val isOpen: Boolean get() = opened && !closed.get() && !disconnected

    /** Claims interfaces and initialises the chip; returns the data endpoints. */
    internal abstract fun claimAndInitialize(): DataEndpoints

    /** Claims [usbInterface] for this port, or throws [IOException] naming it. */
    internal fun claim(usbInterface: UsbInterfaceDescription) {
        if (!transport.claimInterface(usbInterface)) throw IOException("Cannot claim interface ${usbInterface.id} of ${device.ids}")
    }

    /** The bulk IN/OUT endpoints of [usbInterface], or [IOException] when it lacks either. */
    internal fun bulkPairOf(usbInterface: UsbInterfaceDescription): DataEndpoints {
        val read = usbInterface.bulkEndpoint(UsbDirection.IN)
        val write = usbInterface.bulkEndpoint(UsbDirection.OUT)
        if (read == null || write == null) throw IOException("Interface ${usbInterface.id} of ${device.ids} has no bulk endpoint pair")
        return DataEndpoints(read, write)
    }

    /** Checks [settings] against the chip (throwing [UnsupportedSettingException]) and sends them. */
    internal abstract fun applySettings(settings: LineSettings)

    /** Releases what [claimAndInitialize] claimed. Best effort: called on close and failed opens. */
    internal abstract fun releaseInterfaces()

    /**
     * Turns [length] raw bytes at the start of [buffer], received as packets of [packetSize], into
     * payload in place and returns the payload length. Identity here; FTDI strips status bytes.
     */
    internal open fun extractPayload(buffer: ByteArray, length: Int, packetSize: Int): Int = length

    /**
     * How many raw bytes one read transfer asks for when the caller wants [payloadLength]. One packet:
     * a transfer ends early only on a short packet, and Android can drop what a transfer had
     * received when it times out, so a longer transfer could lose data that ended on a packet boundary.
     */
    internal open fun transferLengthFor(payloadLength: Int, packetSize: Int): Int = packetSize

    internal fun open(settings: LineSettings) {
        try {
            endpoints = claimAndInitialize()
            readBuffer = ByteArray(readBufferSize(endpoints.read.maxPacketSize))
            opened = true
            configure(settings)
        } catch (e: Exception) {
            opened = false
            runCatching { releaseInterfaces() }
            throw e
        }
    }

    /**
     * Applies line settings: baud rate, framing, DTR and RTS.
     * @throws UnsupportedSettingException if the chip cannot do them; nothing is sent then.
     * @throws PortDisconnectedException if the device is gone.
     * @throws IOException if the chip rejects a request or the port is closed.
     */
    override fun configure(settings: LineSettings) {
        checkUsable()
        applySettings(settings)
        lineSettings = settings
    }

    /**
     * Reads what the device has sent, up to [length] bytes, waiting at most [timeoutMillis] (0 waits
     * for ever). A read returns as soon as one USB packet arrives; bytes of it beyond [length] are
     * kept for the next read, so nothing is lost.
     *
     * @return bytes read, 0 on timeout (never -1: a USB device is not a finite source).
     * @throws PortDisconnectedException if the device was unplugged.
     * @throws IOException if the port is closed or a transfer fails with the device still attached.
     */
    override fun read(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int {
        checkBounds(buffer, offset, length)
        require(timeoutMillis >= 0) { "timeoutMillis must not be negative, was $timeoutMillis" }
        checkUsable()
        if (length == 0) return 0
        if (pendingEnd > pendingStart) return takePending(buffer, offset, length)
        val deadline = Deadline(clock, timeoutMillis)
        val read = endpoints.read
        while (true) {
            val requested = min(transferLengthFor(length, read.maxPacketSize), readBuffer.size)
            val received = transport.bulkTransfer(read, readBuffer, 0, requested, deadline.transferTimeoutMillis())
            if (received < 0) {
                failIfGone()
                // Android returns -1 for a timeout and for an error alike; the device is still there,
                // so with a deadline this was the timeout. Without one nothing should have ended it.
                if (deadline.isForever) throw IOException("Read from ${device.ids} failed with the device attached")
                return 0
            }
            val payload = if (received == 0) 0 else extractPayload(readBuffer, received, read.maxPacketSize)
            if (payload > 0) {
                pendingStart = 0
                pendingEnd = payload
                return takePending(buffer, offset, length)
            }
            if (deadline.expired()) return 0
        }
    }

    /**
     * Writes all [length] bytes in chunks of the endpoint's max packet size, within [timeoutMillis] in
     * total (0: no deadline). Each transfer gets only the time left.
     *
     * @throws PortTimeoutException if the deadline passes first; some bytes may have been sent.
     * @throws PortDisconnectedException if the device was unplugged.
     * @throws IOException if the port is closed or a transfer fails with the device still attached.
     */
    override fun write(buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int) {
        checkBounds(buffer, offset, length)
        require(timeoutMillis >= 0) { "timeoutMillis must not be negative, was $timeoutMillis" }
        checkUsable()
        val deadline = Deadline(clock, timeoutMillis)
        val write = endpoints.write
        var written = 0
        while (written < length) {
            if (written > 0 && deadline.expired()) throw writeTimeout(written, length, timeoutMillis)
            val chunk = min(length - written, write.maxPacketSize)
            val sent = transport.bulkTransfer(write, buffer, offset + written, chunk, deadline.transferTimeoutMillis())
            if (sent < 0) {
                failIfGone()
                if (deadline.expired()) throw writeTimeout(written, length, timeoutMillis)
                throw IOException("Write to ${device.ids} failed after $written of $length bytes")
            }
            written += sent
        }
    }

    /**
     * Tells the port its device is gone (a detach broadcast arrived): reads and writes from now on,
     * and one blocked in a transfer when the transport is closed, throw [PortDisconnectedException].
     */
    public fun onDeviceDetached() {
        disconnected = true
    }

    /** Releases the port's interfaces (best effort: the device may be gone). Idempotent. */
    override fun close() {
        if (!closed.compareAndSet(false, true)) return
        if (opened && !disconnected) runCatching { releaseInterfaces() }
    }

    /** A control transfer that must succeed; IN transfers must return [length] bytes. */
    internal fun control(requestType: Int, request: Int, value: Int, index: Int, data: ByteArray? = null, what: String): Int {
        val length = data?.size ?: 0
        val result = transport.controlTransfer(requestType, request, value, index, data, length, CONTROL_TIMEOUT_MILLIS)
        val isIn = requestType and 0x80 != 0
        if (result < 0 || (isIn && result != length)) {
            failIfGone()
            throw IOException("$what failed on ${device.ids} (result $result)")
        }
        return result
    }

    /** Throws the exception that says why the port cannot be used, if it cannot. */
    internal fun failIfGone() {
        if (disconnected) throw PortDisconnectedException("USB device ${device.ids} was unplugged")
        if (closed.get()) throw IOException("Port $portIndex of ${device.ids} is closed")
        if (!transport.isDeviceAttached()) {
            disconnected = true
            throw PortDisconnectedException("USB device ${device.ids} was unplugged")
        }
    }

    private fun checkUsable() {
        if (disconnected) throw PortDisconnectedException("USB device ${device.ids} was unplugged")
        if (closed.get() || !opened) throw IOException("Port $portIndex of ${device.ids} is closed")
    }

    private fun takePending(buffer: ByteArray, offset: Int, length: Int): Int {
        val count = min(length, pendingEnd - pendingStart)
        System.arraycopy(readBuffer, pendingStart, buffer, offset, count)
        pendingStart += count
        return count
    }

    private fun writeTimeout(written: Int, length: Int, timeoutMillis: Int) =
        PortTimeoutException("Wrote $written of $length bytes to ${device.ids} before the $timeoutMillis ms deadline")

    private companion object {
        /** 16 KiB: Android before API 28 caps one bulk transfer there. Whole packets, so none overflow. */
        const val MAX_TRANSFER_BYTES = 16 * 1024

        fun readBufferSize(packetSize: Int): Int = maxOf(packetSize, MAX_TRANSFER_BYTES / packetSize * packetSize)

        fun checkBounds(buffer: ByteArray, offset: Int, length: Int) {
            if (offset < 0 || length < 0 || offset + length > buffer.size) {
                throw IndexOutOfBoundsException("offset $offset and length $length do not fit a buffer of ${buffer.size}")
            }
        }
    }
}
