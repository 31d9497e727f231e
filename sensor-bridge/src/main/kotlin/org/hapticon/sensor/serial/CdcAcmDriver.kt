package org.hapticon.sensor.serial

import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.StopBits

/**
 * USB CDC ACM, the class that native-USB boards speak: Arduino Uno R3/Mega (16U2), Leonardo and
 * Micro, Teensy, ESP32-S2/S3, RP2040, and any unknown device with a CDC control and data interface.
 *
 * Composite devices (a HID or vendor interface beside the serial one, one port per ACM function)
 * are handled by pairing each ACM control interface with its data interface: the class 10
 * interface numbered right after it, as interface association descriptors lay them out, else the
 * next unused one. A device with a single interface carrying both bulk endpoints works too.
 */
public class CdcAcmDriver(override val device: UsbDeviceDescription) : UsbSerialDriver {
    override val chipFamily: String get() = "CDC-ACM"

    private val functions: List<AcmFunction> = findAcmFunctions(device)

    override val portCount: Int get() = functions.size

    override fun openPort(transport: UsbTransport, portIndex: Int, settings: LineSettings, clock: MonotonicClock): UsbSerialPort {
        requirePortIndex(portIndex)
        return CdcAcmPort(device, portIndex, transport, clock, functions[portIndex]).also { it.open(settings) }
    }

    /** Probing by class. */
    public companion object {
        /** Whether [device] has a CDC ACM serial function this driver can open. */
        public fun isCdcAcm(device: UsbDeviceDescription): Boolean = findAcmFunctions(device).isNotEmpty()
    }
}

/** One serial function: the interface that takes class requests and the one with the bulk endpoints. */
internal class AcmFunction(val control: UsbInterfaceDescription, val data: UsbInterfaceDescription)

internal fun findAcmFunctions(device: UsbDeviceDescription): List<AcmFunction> {
    val dataInterfaces = device.interfaces.filter { it.interfaceClass == UsbClass.CDC_DATA && it.hasBulkPair() }
    val controls = device.interfaces
        .filter { it.interfaceClass == UsbClass.CDC_COMMUNICATIONS && it.interfaceSubclass == UsbClass.CDC_SUBCLASS_ACM }
        .distinctBy { it.id }
    val used = mutableSetOf<Int>()
    val functions = controls.mapNotNull { control ->
        val data = dataInterfaces.firstOrNull { it.id == control.id + 1 && it.id !in used }
            ?: dataInterfaces.firstOrNull { it.id > control.id && it.id !in used }
            ?: (if (control.hasBulkPair()) control else null)
        data?.let { used += it.id; AcmFunction(control, it) }
    }
    if (functions.isNotEmpty()) return functions
    // Devices that put everything on one communications or data interface: class requests go there.
    val single = device.interfaces.firstOrNull {
        (it.interfaceClass == UsbClass.CDC_COMMUNICATIONS || it.interfaceClass == UsbClass.CDC_DATA) && it.hasBulkPair()
    }
    return listOfNotNull(single?.let { AcmFunction(it, it) })
}

/** CDC PSTN requests (CDC PSTN subclass 1.2, §6.3), sent to the control interface. */
private object AcmRequest {
    const val SET_LINE_CODING = 0x20
    const val SET_CONTROL_LINE_STATE = 0x22
    const val LINE_STATE_DTR = 0x01
    const val LINE_STATE_RTS = 0x02
}

internal class CdcAcmPort(
    device: UsbDeviceDescription,
    portIndex: Int,
    transport: UsbTransport,
    clock: MonotonicClock,
    private val function: AcmFunction,
) : UsbSerialPort(device, portIndex, transport, clock) {
    private val claimed = mutableListOf<UsbInterfaceDescription>()

    override fun claimAndInitialize(): DataEndpoints {
        for (usbInterface in listOf(function.control, function.data).distinctBy { it.id }) {
            claim(usbInterface)
            claimed += usbInterface
        }
        return bulkPairOf(function.data)
    }

    override fun applySettings(settings: LineSettings) {
        // Line coding: dwDTERate, bCharFormat, bParityType, bDataBits.
        val lineCoding = littleEndian32(settings.baudRate) +
            byteArrayOf(charFormat(settings.stopBits), settings.parity.usbCode.toByte(), settings.dataBits.toByte())
        val index = function.control.id
        control(UsbRequestType.CLASS_INTERFACE_OUT, AcmRequest.SET_LINE_CODING, 0, index, lineCoding, "SET_LINE_CODING")
        val lines = (if (settings.dtr) AcmRequest.LINE_STATE_DTR else 0) or (if (settings.rts) AcmRequest.LINE_STATE_RTS else 0)
        control(UsbRequestType.CLASS_INTERFACE_OUT, AcmRequest.SET_CONTROL_LINE_STATE, lines, index, null, "SET_CONTROL_LINE_STATE")
    }

    override fun releaseInterfaces() {
        claimed.asReversed().forEach { runCatching { transport.releaseInterface(it) } }
        claimed.clear()
    }

    private fun charFormat(stopBits: StopBits): Byte = when (stopBits) {
        StopBits.ONE -> 0
        StopBits.ONE_POINT_FIVE -> 1
        StopBits.TWO -> 2
    }
}
