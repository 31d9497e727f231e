package org.hapticon.sensor.usb

import android.hardware.usb.UsbDevice
import android.hardware.usb.UsbEndpoint
import android.hardware.usb.UsbInterface
import org.hapticon.sensor.serial.UsbDeviceDescription
import org.hapticon.sensor.serial.UsbEndpointDescription
import org.hapticon.sensor.serial.UsbEndpointType
import org.hapticon.sensor.serial.UsbInterfaceDescription

/** What the pure drivers need to know about this device: ids, class, and every interface with its endpoints. */
fun UsbDevice.toDescription(): UsbDeviceDescription = UsbDeviceDescription(
    vendorId = vendorId,
    productId = productId,
    interfaces = (0 until interfaceCount).map { getInterface(it).toDescription() },
    deviceClass = deviceClass,
    name = deviceName,
    productName = productName,
)

/** This interface (one alternate setting) as the pure drivers see it. */
fun UsbInterface.toDescription(): UsbInterfaceDescription = UsbInterfaceDescription(
    id = id,
    interfaceClass = interfaceClass,
    interfaceSubclass = interfaceSubclass,
    interfaceProtocol = interfaceProtocol,
    endpoints = (0 until endpointCount).map { getEndpoint(it).toDescription() },
    alternateSetting = alternateSetting,
)

/** This endpoint as the pure drivers see it. */
fun UsbEndpoint.toDescription(): UsbEndpointDescription =
    UsbEndpointDescription(address, UsbEndpointType.fromAttributes(type), maxPacketSize)

/** `vvvv:pppp` in lower-case hex, as `lsusb` prints it. */
internal val UsbDevice.usbIds: String get() = "%04x:%04x".format(vendorId, productId)
