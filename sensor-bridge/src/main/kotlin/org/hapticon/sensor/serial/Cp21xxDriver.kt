package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.StopBits

/**
 * Silicon Labs CP210x USB-UART chips (CP2102, CP2102N, CP2104 and the multi-port CP2105/CP2108, one
 * port per interface), as on many ESP32 DevKits and NodeMCU boards (Silicon Labs AN571).
 */
public class Cp21xxDriver(override val device: UsbDeviceDescription) : UsbSerialDriver {
    override val chipFamily: String get() = "CP210x"

    private val portInterfaces = device.interfaces.distinctBy { it.id }

    override val portCount: Int get() = portInterfaces.size

    override fun openPort(transport: UsbTransport, portIndex: Int, settings: LineSettings, clock: MonotonicClock): UsbSerialPort {
        requirePortIndex(portIndex)
        return Cp21xxPort(device, portIndex, transport, clock, portInterfaces[portIndex]).also { it.open(settings) }
    }
}

/** CP210x vendor requests (AN571 §5), all addressed to the port's interface. */
private object Cp21xxRequest {
    const val IFC_ENABLE = 0x00
    const val SET_LINE_CTL = 0x03
    const val SET_MHS = 0x07
    const val SET_BAUDRATE = 0x1E

    const val UART_ENABLE = 0x0001
    const val UART_DISABLE = 0x0000
    const val MHS_DTR = 0x0001
    const val MHS_RTS = 0x0002

    // SET_MHS bits 8 and 9 say "change DTR" and "change RTS"; without them the chip ignores bits 0 and 1.
    const val MHS_WRITE_DTR = 0x0100
    const val MHS_WRITE_RTS = 0x0200

    /** No CP210x generates more (the CP2102N's limit; older parts stop at 921600 or 2000000). */
    const val MAX_BAUD_RATE = 3_000_000
}

internal class Cp21xxPort(
    device: UsbDeviceDescription,
    portIndex: Int,
    transport: UsbTransport,
    clock: MonotonicClock,
    usbInterface: UsbInterfaceDescription,
) : SingleInterfacePort(device, portIndex, transport, clock, usbInterface) {
    private val index = usbInterface.id

    override fun initializeChip() {
        control(UsbRequestType.VENDOR_INTERFACE_OUT, Cp21xxRequest.IFC_ENABLE, Cp21xxRequest.UART_ENABLE, index, null, "CP210x IFC_ENABLE")
    }

    override fun applySettings(settings: LineSettings) {
        if (settings.baudRate > Cp21xxRequest.MAX_BAUD_RATE) {
            throw UnsupportedSettingException("CP210x chips run at most ${Cp21xxRequest.MAX_BAUD_RATE} baud, not ${settings.baudRate}")
        }
        if (settings.stopBits == StopBits.ONE_POINT_FIVE) throw UnsupportedSettingException("CP210x chips do not do 1.5 stop bits")
        setBaudRate(settings.baudRate)
        // SET_LINE_CTL: bits 0..3 stop bits (0 = 1, 2 = 2), 4..7 parity, 8..15 data bits.
        val lineControl = (if (settings.stopBits == StopBits.TWO) 2 else 0) or (settings.parity.usbCode shl 4) or (settings.dataBits shl 8)
        control(UsbRequestType.VENDOR_INTERFACE_OUT, Cp21xxRequest.SET_LINE_CTL, lineControl, index, null, "CP210x SET_LINE_CTL")
        val lines = Cp21xxRequest.MHS_WRITE_DTR or Cp21xxRequest.MHS_WRITE_RTS or
            (if (settings.dtr) Cp21xxRequest.MHS_DTR else 0) or (if (settings.rts) Cp21xxRequest.MHS_RTS else 0)
        control(UsbRequestType.VENDOR_INTERFACE_OUT, Cp21xxRequest.SET_MHS, lines, index, null, "CP210x SET_MHS")
    }

    /** The chip stalls SET_BAUDRATE for a rate it cannot generate: report that as the setting's fault. */
    private fun setBaudRate(baudRate: Int) {
        val data = littleEndian32(baudRate)
        val result = transport.controlTransfer(
            UsbRequestType.VENDOR_INTERFACE_OUT, Cp21xxRequest.SET_BAUDRATE, 0, index, data, data.size, CONTROL_TIMEOUT_MILLIS,
        )
        if (result < 0) {
            failIfGone()
            throw UnsupportedSettingException("CP210x on ${device.ids} rejected $baudRate baud")
        }
    }

    override fun releaseInterfaces() {
        // Disabling the UART lets the chip drop DTR/RTS and stop buffering for a host that left.
        runCatching {
            transport.controlTransfer(
                UsbRequestType.VENDOR_INTERFACE_OUT, Cp21xxRequest.IFC_ENABLE, Cp21xxRequest.UART_DISABLE, index, null, 0, CONTROL_TIMEOUT_MILLIS,
            )
        }
        super.releaseInterfaces()
    }
}
