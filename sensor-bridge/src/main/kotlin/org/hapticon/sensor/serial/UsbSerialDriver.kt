package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import org.hapticon.sensor.port.LineSettings

/**
 * A chip family's driver for one USB device: knows how many serial ports the device has and how to
 * open one. Made by a [UsbSerialDriverFactory] from a [ProbeTable] or by [UsbSerialProber].
 */
public interface UsbSerialDriver {
    /** The device this driver was made for. */
    public val device: UsbDeviceDescription

    /** The chip family, for logs and the UI: `CDC-ACM`, `FTDI`, `CP210x`, `CH34x`. */
    public val chipFamily: String

    /** How many serial ports the device has (FT2232H and CP2105 have 2, most have 1). */
    public val portCount: Int

    /**
     * Claims the port's interfaces, initialises the chip and applies [settings] (so DTR and RTS are
     * asserted unless [settings] says otherwise). The caller keeps ownership of [transport]: close the
     * port first, then the transport.
     *
     * @throws IllegalArgumentException if [portIndex] is not in 0 until [portCount].
     * @throws UnsupportedSettingException if the chip cannot do [settings].
     * @throws java.io.IOException if an interface cannot be claimed or the chip rejects a request.
     */
    public fun openPort(
        transport: UsbTransport,
        portIndex: Int = 0,
        settings: LineSettings = LineSettings(),
        clock: MonotonicClock = MonotonicClock.SYSTEM,
    ): UsbSerialPort
}

/** Makes a driver for a device; the constructors of the drivers are factories (`::FtdiDriver`). */
public fun interface UsbSerialDriverFactory {
    /** The driver for [device]. */
    public fun create(device: UsbDeviceDescription): UsbSerialDriver
}

/** Common argument checks for [UsbSerialDriver.openPort]. */
internal fun UsbSerialDriver.requirePortIndex(portIndex: Int) {
    require(portIndex in 0 until portCount) { "$chipFamily device ${device.ids} has $portCount port(s), no port $portIndex" }
}
