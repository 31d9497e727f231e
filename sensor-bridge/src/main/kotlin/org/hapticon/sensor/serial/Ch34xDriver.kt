package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.Parity
import org.hapticon.sensor.port.StopBits
import java.io.IOException

/**
 * WCH CH340/CH341 USB-UART chips, as on most low-cost Arduino Nano and Uno clones and ESP8266
 * boards. One port. The request sequence follows the Linux ch341 driver: read the chip version,
 * serial init, then divisor, line control and modem control.
 */
public class Ch34xDriver(override val device: UsbDeviceDescription) : UsbSerialDriver {
    override val chipFamily: String get() = "CH34x"

    override val portCount: Int get() = 1

    override fun openPort(transport: UsbTransport, portIndex: Int, settings: LineSettings, clock: MonotonicClock): UsbSerialPort {
        requirePortIndex(portIndex)
        val dataInterface = device.interfaces.lastOrNull { it.hasBulkPair() }
            ?: throw IOException("CH34x device ${device.ids} has no interface with bulk endpoints")
        return Ch34xPort(device, transport, clock, dataInterface).also { it.open(settings) }
    }
}

/** CH34x vendor requests and registers. */
private object Ch34xRequest {
    const val READ_VERSION = 0x5F
    const val WRITE_REGISTERS = 0x9A
    const val SERIAL_INIT = 0xA1
    const val MODEM_CONTROL = 0xA4

    // WRITE_REGISTERS writes two registers at once: wValue = second << 8 | first, wIndex = their values.
    const val PRESCALER_AND_DIVISOR = 0x1312
    const val LCR_AND_LCR2 = 0x2518

    const val LCR_ENABLE_RX = 0x80
    const val LCR_ENABLE_TX = 0x40
    const val LCR_MARK_SPACE = 0x20
    const val LCR_EVEN = 0x10
    const val LCR_PARITY = 0x08
    const val LCR_TWO_STOP_BITS = 0x04

    const val MCR_DTR = 0x20
    const val MCR_RTS = 0x40

    /** Without this bit the CH341A holds received bytes until a full 32-byte packet is there. */
    const val DIVISOR_SEND_AT_ONCE = 0x80
}

internal class Ch34xPort(
    device: UsbDeviceDescription,
    transport: UsbTransport,
    clock: MonotonicClock,
    usbInterface: UsbInterfaceDescription,
) : SingleInterfacePort(device, 0, transport, clock, usbInterface) {
    /** Chip version from READ_VERSION: 0x27 on old CH340s, 0x30 and up on current parts. */
    internal var version: Int = 0
        private set

    override fun initializeChip() {
        val reply = ByteArray(2)
        control(UsbRequestType.VENDOR_DEVICE_IN, Ch34xRequest.READ_VERSION, 0, 0, reply, "CH34x READ_VERSION")
        version = reply[0].toInt() and 0xFF
        control(UsbRequestType.VENDOR_DEVICE_OUT, Ch34xRequest.SERIAL_INIT, 0, 0, null, "CH34x SERIAL_INIT")
    }

    override fun applySettings(settings: LineSettings) {
        if (settings.stopBits == StopBits.ONE_POINT_FIVE) throw UnsupportedSettingException("CH34x chips do not do 1.5 stop bits")
        val framedAs8N1 = settings.dataBits == 8 && settings.parity == Parity.NONE && settings.stopBits == StopBits.ONE
        // Chips before version 0x30 keep framing in other, undocumented registers: only their default 8N1 is known to work.
        if (version < 0x30 && !framedAs8N1) {
            throw UnsupportedSettingException("CH34x version 0x%02x supports only 8N1".format(version))
        }
        var divisor = ch34xBaudDivisor(settings.baudRate)
        // At least one version 0x27 chip has this bit inverted, so it is set only on later ones (as Linux does).
        if (version > 0x27) divisor = divisor or Ch34xRequest.DIVISOR_SEND_AT_ONCE
        control(UsbRequestType.VENDOR_DEVICE_OUT, Ch34xRequest.WRITE_REGISTERS, Ch34xRequest.PRESCALER_AND_DIVISOR, divisor, null, "CH34x baud rate")
        if (version >= 0x30) {
            control(UsbRequestType.VENDOR_DEVICE_OUT, Ch34xRequest.WRITE_REGISTERS, Ch34xRequest.LCR_AND_LCR2, lineControl(settings), null, "CH34x line control")
        }
        val modem = (if (settings.dtr) Ch34xRequest.MCR_DTR else 0) or (if (settings.rts) Ch34xRequest.MCR_RTS else 0)
        // The chip's modem-control lines are active low: it takes the inverted bits.
        control(UsbRequestType.VENDOR_DEVICE_OUT, Ch34xRequest.MODEM_CONTROL, modem.inv() and 0xFFFF, 0, null, "CH34x modem control")
    }

    private fun lineControl(settings: LineSettings): Int {
        val parity = when (settings.parity) {
            Parity.NONE -> 0
            Parity.ODD -> Ch34xRequest.LCR_PARITY
            Parity.EVEN -> Ch34xRequest.LCR_PARITY or Ch34xRequest.LCR_EVEN
            Parity.MARK -> Ch34xRequest.LCR_PARITY or Ch34xRequest.LCR_MARK_SPACE
            Parity.SPACE -> Ch34xRequest.LCR_PARITY or Ch34xRequest.LCR_MARK_SPACE or Ch34xRequest.LCR_EVEN
        }
        val stop = if (settings.stopBits == StopBits.TWO) Ch34xRequest.LCR_TWO_STOP_BITS else 0
        // Data bits 5..8 are codes 0..3 in bits 0..1.
        return Ch34xRequest.LCR_ENABLE_RX or Ch34xRequest.LCR_ENABLE_TX or parity or stop or (settings.dataBits - 5)
    }
}
