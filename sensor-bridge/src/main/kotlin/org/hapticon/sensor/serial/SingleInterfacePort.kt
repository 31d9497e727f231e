package org.hapticon.sensor.serial

import org.hapticon.sensor.port.Parity

/**
 * A port that is one USB interface carrying its own bulk IN/OUT pair and driven by vendor requests:
 * FTDI, CP210x and CH34x. Claiming that interface, finding its endpoints and releasing it are the
 * same for every such chip, so only [initializeChip] and the line settings differ (as
 * usb-serial-for-android's `CommonUsbSerialPort` holds the shared state of its per-chip ports).
 */
internal abstract class SingleInterfacePort(
    device: UsbDeviceDescription,
    portIndex: Int,
    transport: UsbTransport,
    clock: MonotonicClock,
    protected val usbInterface: UsbInterfaceDescription,
) : UsbSerialPort(device, portIndex, transport, clock) {
    final override fun claimAndInitialize(): DataEndpoints {
        claim(usbInterface)
        val endpoints = bulkPairOf(usbInterface)
        initializeChip()
        return endpoints
    }

    /** The chip's own requests once its interface is claimed (reset, enable, read its version…). */
    protected abstract fun initializeChip()

    override fun releaseInterfaces() {
        transport.releaseInterface(usbInterface)
    }
}

/**
 * The parity code the USB serial chips take in a 3- or 4-bit field: 0 none, 1 odd, 2 even, 3 mark,
 * 4 space. The same numbering in CDC PSTN 1.2 Table 17 (SET_LINE_CODING bParityType), Silicon Labs
 * AN571 §5.6 (CP210x SET_LINE_CTL bits 4..7) and FTDI's SIO SET_DATA bits 8..10.
 */
internal val Parity.usbCode: Int
    get() = when (this) {
        Parity.NONE -> 0
        Parity.ODD -> 1
        Parity.EVEN -> 2
        Parity.MARK -> 3
        Parity.SPACE -> 4
    }
