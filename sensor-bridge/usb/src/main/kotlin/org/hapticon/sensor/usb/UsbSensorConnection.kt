package org.hapticon.sensor.usb

import android.hardware.usb.UsbDevice
import org.hapticon.sensor.port.SerialPort
import org.hapticon.sensor.serial.UsbSerialDriver
import org.hapticon.sensor.serial.UsbSerialPort
import java.io.Closeable
import java.util.concurrent.atomic.AtomicBoolean

/**
 * An open serial port on a USB device, from [UsbSensorOpener]. It is a [SerialPort]; when the device
 * is unplugged it closes itself, and reads and writes (also one blocked at that moment) throw
 * [org.hapticon.sensor.port.PortDisconnectedException].
 */
class UsbSensorConnection internal constructor(
    /** The device. */
    val device: UsbDevice,
    /** The driver serving it. */
    val driver: UsbSerialDriver,
    private val port: UsbSerialPort,
    private val transport: AndroidUsbTransport,
) : SerialPort by port {
    @Volatile private var detachRegistration: Closeable? = null
    private val closed = AtomicBoolean(false)

    internal fun watchDetach(monitor: UsbDeviceMonitor) {
        detachRegistration = monitor.addDetachListener { gone -> if (gone.deviceName == device.deviceName) onDetached() }
    }

    /** The device was unplugged: mark the port gone first, so a read woken by closing the connection reports that. */
    internal fun onDetached() {
        transport.markDetached()
        port.onDeviceDetached()
        close()
    }

    /** Releases the interfaces (unless the device is gone) and closes the USB connection. Idempotent. */
    override fun close() {
        if (!closed.compareAndSet(false, true)) return
        detachRegistration?.close()
        detachRegistration = null
        port.close()
        transport.close()
    }
}
