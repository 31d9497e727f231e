package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.StopBits
import java.io.IOException

/**
 * FTDI USB-UART chips: FT232R, FT231X/FT230X, FT232H, and the multi-port FT2232/FT4232 (one port per
 * interface). Every bulk IN packet starts with 2 modem-status bytes, which reads strip.
 */
public class FtdiDriver(override val device: UsbDeviceDescription) : UsbSerialDriver {
    override val chipFamily: String get() = "FTDI"

    private val portInterfaces = device.interfaces.distinctBy { it.id }

    override val portCount: Int get() = portInterfaces.size

    override fun openPort(transport: UsbTransport, portIndex: Int, settings: LineSettings, clock: MonotonicClock): UsbSerialPort {
        requirePortIndex(portIndex)
        return FtdiPort(device, portIndex, transport, clock, portInterfaces[portIndex], multiPort = portCount > 1)
            .also { it.open(settings) }
    }
}

/** Vendor requests of the FTDI SIO protocol. */
private object FtdiRequest {
    const val RESET = 0x00
    const val MODEM_CONTROL = 0x01
    const val SET_BAUD_RATE = 0x03
    const val SET_DATA = 0x04
    const val SET_LATENCY_TIMER = 0x09

    const val RESET_SIO = 0
    // MODEM_CONTROL: the high byte says which lines to change, the low byte their new state.
    const val DTR_ON = 0x0101
    const val DTR_OFF = 0x0100
    const val RTS_ON = 0x0202
    const val RTS_OFF = 0x0200

    /** The chip sends what it has after this many ms; the default 16 adds that much latency to sensor data. */
    const val LATENCY_MILLIS = 1

    const val STATUS_BYTES = 2
}

internal class FtdiPort(
    device: UsbDeviceDescription,
    portIndex: Int,
    transport: UsbTransport,
    clock: MonotonicClock,
    usbInterface: UsbInterfaceDescription,
    multiPort: Boolean,
) : SingleInterfacePort(device, portIndex, transport, clock, usbInterface) {
    /** wIndex names the channel: A = 1, B = 2, … */
    private val channel = usbInterface.id + 1
    private var baudIndexNamesChannel = multiPort

    override fun initializeChip() {
        // The H chips (bcdDevice 7.00 FT2232H, 8.00 FT4232H, 9.00 FT232H) read the channel from the low
        // byte of SET_BAUD_RATE's wIndex and the divisor bit from the high byte, like multi-port chips.
        val descriptors = transport.rawDescriptors()
        if (descriptors != null && descriptors.size >= 14 && descriptors[13].toInt() in 7..9) baudIndexNamesChannel = true
        control(UsbRequestType.VENDOR_DEVICE_OUT, FtdiRequest.RESET, FtdiRequest.RESET_SIO, channel, null, "FTDI reset")
        control(UsbRequestType.VENDOR_DEVICE_OUT, FtdiRequest.SET_LATENCY_TIMER, FtdiRequest.LATENCY_MILLIS, channel, null, "FTDI latency timer")
    }

    override fun applySettings(settings: LineSettings) {
        if (settings.dataBits < 7) throw UnsupportedSettingException("FTDI chips send 7 or 8 data bits, not ${settings.dataBits}")
        if (settings.stopBits == StopBits.ONE_POINT_FIVE) throw UnsupportedSettingException("FTDI chips do not do 1.5 stop bits")
        val divisor = ftdiBaudDivisor(settings.baudRate)
        val baudIndex = if (baudIndexNamesChannel) (divisor.indexBit shl 8) or channel else divisor.indexBit
        control(UsbRequestType.VENDOR_DEVICE_OUT, FtdiRequest.SET_BAUD_RATE, divisor.value, baudIndex, null, "FTDI SET_BAUD_RATE")
        // SET_DATA: bits 0..7 data bits, 8..10 parity (none, odd, even, mark, space), 11..13 stop bits.
        val dataFormat = settings.dataBits or (settings.parity.usbCode shl 8) or (if (settings.stopBits == StopBits.TWO) 2 shl 11 else 0)
        control(UsbRequestType.VENDOR_DEVICE_OUT, FtdiRequest.SET_DATA, dataFormat, channel, null, "FTDI SET_DATA")
        val lines = (if (settings.dtr) FtdiRequest.DTR_ON else FtdiRequest.DTR_OFF) or (if (settings.rts) FtdiRequest.RTS_ON else FtdiRequest.RTS_OFF)
        control(UsbRequestType.VENDOR_DEVICE_OUT, FtdiRequest.MODEM_CONTROL, lines, channel, null, "FTDI MODEM_CONTROL")
    }

    /** Every packet of a transfer starts with the 2 modem-status bytes; only the rest is data. */
    override fun extractPayload(buffer: ByteArray, length: Int, packetSize: Int): Int {
        var payloadEnd = 0
        var packetStart = 0
        while (packetStart < length) {
            val packetLength = minOf(packetSize, length - packetStart)
            if (packetLength < FtdiRequest.STATUS_BYTES) throw IOException("FTDI packet of $packetLength bytes has no status header")
            val payload = packetLength - FtdiRequest.STATUS_BYTES
            System.arraycopy(buffer, packetStart + FtdiRequest.STATUS_BYTES, buffer, payloadEnd, payload)
            payloadEnd += payload
            packetStart += packetSize
        }
        return payloadEnd
    }

    /**
     * Enough whole packets for [payloadLength], each carrying 2 bytes fewer than its size. Safe with
     * several packets because the chip ends every burst with a short packet when its latency timer
     * fires, and needed because one packet per transfer cannot keep up at Mbaud rates.
     */
    override fun transferLengthFor(payloadLength: Int, packetSize: Int): Int {
        val perPacket = packetSize - FtdiRequest.STATUS_BYTES
        return (payloadLength + perPacket - 1) / perPacket * packetSize
    }
}
