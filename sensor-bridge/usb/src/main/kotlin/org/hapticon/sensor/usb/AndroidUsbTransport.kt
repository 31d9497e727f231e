package org.hapticon.sensor.usb

import android.hardware.usb.UsbDevice
import android.hardware.usb.UsbDeviceConnection
import android.hardware.usb.UsbEndpoint
import android.hardware.usb.UsbInterface
import org.hapticon.sensor.serial.UsbEndpointDescription
import org.hapticon.sensor.serial.UsbInterfaceDescription
import org.hapticon.sensor.serial.UsbTransport
import java.io.Closeable

/**
 * The pure drivers' [UsbTransport] over an open [UsbDeviceConnection]: descriptions are mapped back to
 * the device's [UsbInterface] and [UsbEndpoint] objects, every call passes straight through.
 * Closing it closes the connection, which also ends a transfer blocked in another thread.
 */
class AndroidUsbTransport(device: UsbDevice, private val connection: UsbDeviceConnection) : UsbTransport, Closeable {
    private val interfaces = HashMap<Pair<Int, Int>, UsbInterface>()
    private val endpoints = HashMap<Int, UsbEndpoint>()

    @Volatile private var detached = false

    init {
        for (i in 0 until device.interfaceCount) {
            val usbInterface = device.getInterface(i)
            interfaces[usbInterface.id to usbInterface.alternateSetting] = usbInterface
            for (e in 0 until usbInterface.endpointCount) {
                val endpoint = usbInterface.getEndpoint(e)
                endpoints.putIfAbsent(endpoint.address, endpoint)
            }
        }
    }

    /** Records that a detach broadcast named this device, so [isDeviceAttached] answers without asking it. */
    fun markDetached() {
        detached = true
    }

    override fun claimInterface(usbInterface: UsbInterfaceDescription): Boolean =
        connection.claimInterface(interfaceFor(usbInterface), true)

    override fun releaseInterface(usbInterface: UsbInterfaceDescription): Boolean =
        connection.releaseInterface(interfaceFor(usbInterface))

    override fun controlTransfer(requestType: Int, request: Int, value: Int, index: Int, data: ByteArray?, length: Int, timeoutMillis: Int): Int =
        connection.controlTransfer(requestType, request, value, index, data, length, timeoutMillis)

    override fun bulkTransfer(endpoint: UsbEndpointDescription, buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int {
        val usbEndpoint = endpoints[endpoint.address] ?: throw IllegalArgumentException("No endpoint 0x%02x on this device".format(endpoint.address))
        return connection.bulkTransfer(usbEndpoint, buffer, offset, length, timeoutMillis)
    }

    override fun isDeviceAttached(): Boolean {
        if (detached) return false
        // Standard GET_STATUS to the device: every device answers it, and it fails at once when the
        // device is gone, whereas a bulk transfer returns -1 for both a timeout and an unplug.
        val status = ByteArray(2)
        return connection.controlTransfer(GET_STATUS_REQUEST_TYPE, GET_STATUS, 0, 0, status, status.size, GET_STATUS_TIMEOUT_MILLIS) >= 0
    }

    override fun rawDescriptors(): ByteArray? = connection.rawDescriptors

    override fun close() {
        connection.close()
    }

    private fun interfaceFor(description: UsbInterfaceDescription): UsbInterface =
        interfaces[description.id to description.alternateSetting]
            ?: throw IllegalArgumentException("No interface ${description.id} (alternate ${description.alternateSetting}) on this device")

    private companion object {
        const val GET_STATUS_REQUEST_TYPE = 0x80
        const val GET_STATUS = 0x00
        const val GET_STATUS_TIMEOUT_MILLIS = 200
    }
}
