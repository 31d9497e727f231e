package org.hapticon.testing.android

import android.hardware.usb.UsbConfiguration
import android.hardware.usb.UsbDevice
import android.hardware.usb.UsbEndpoint
import android.hardware.usb.UsbInterface
import android.os.Parcelable
import java.lang.reflect.Proxy

/**
 * Real [UsbDevice] objects for Robolectric tests (the app's and sensor-bridge:usb's). Their constructors are hidden
 * from the public SDK, so they are reached by reflection (Robolectric 4.17 has no builder for them).
 */
object AndroidTestDevices {
    private val int = Int::class.javaPrimitiveType!!
    private val boolean = Boolean::class.javaPrimitiveType!!

    fun endpoint(address: Int, type: Int, maxPacketSize: Int): UsbEndpoint =
        UsbEndpoint::class.java.getConstructor(int, int, int, int).newInstance(address, type, maxPacketSize, 0)

    fun bulk(address: Int, maxPacketSize: Int = 64) = endpoint(address, 2, maxPacketSize)

    fun interrupt(address: Int) = endpoint(address, 3, 8)

    fun usbInterface(id: Int, usbClass: Int, subclass: Int, protocol: Int, vararg endpoints: UsbEndpoint): UsbInterface {
        val usbInterface = UsbInterface::class.java
            .getConstructor(int, int, String::class.java, int, int, int)
            .newInstance(id, 0, null, usbClass, subclass, protocol)
        UsbInterface::class.java.getMethod("setEndpoints", Array<Parcelable>::class.java).invoke(usbInterface, arrayOf<Parcelable>(*endpoints))
        return usbInterface
    }

    /** A device with [interfaces] in one configuration, made by "Maker", named [product]. */
    fun device(name: String, vendorId: Int, productId: Int, deviceClass: Int, vararg interfaces: UsbInterface, product: String = "Board"): UsbDevice {
        val configuration = UsbConfiguration::class.java.getConstructor(int, String::class.java, int, int).newInstance(1, null, 0x80, 50)
        UsbConfiguration::class.java.getMethod("setInterfaces", Array<Parcelable>::class.java).invoke(configuration, arrayOf<Parcelable>(*interfaces))
        val builderClass = Class.forName("android.hardware.usb.UsbDevice\$Builder")
        val builder = builderClass.getConstructor(
            String::class.java, int, int, int, int, int, String::class.java, String::class.java, String::class.java,
            Array<UsbConfiguration>::class.java, String::class.java, boolean, boolean, boolean, boolean, boolean,
        ).newInstance(name, vendorId, productId, deviceClass, 0, 0, "Maker", product, "1.00", arrayOf(configuration), "SN1", false, false, false, false, false)
        val readerClass = Class.forName("android.hardware.usb.IUsbSerialReader")
        val reader = Proxy.newProxyInstance(readerClass.classLoader, arrayOf(readerClass)) { _, method, _ ->
            if (method.name == "getSerial") "SN1" else null
        }
        return builderClass.getMethod("build", readerClass).invoke(builder, reader) as UsbDevice
    }

    /** Arduino Uno R3: CDC control at 0, data at 1 (OUT 0x04, IN 0x83); its product name is [product]. */
    fun arduinoUno(name: String = "/dev/bus/usb/001/002", product: String = "Board") = device(
        name, 0x2341, 0x0043, 0x02,
        usbInterface(0, 0x02, 0x02, 0x01, interrupt(0x82)),
        usbInterface(1, 0x0A, 0x00, 0x00, bulk(0x04), bulk(0x83)),
        product = product,
    )

    /** An FT232R. */
    fun ft232r(name: String = "/dev/bus/usb/001/003") = device(name, 0x0403, 0x6001, 0x00, usbInterface(0, 0xFF, 0xFF, 0xFF, bulk(0x81), bulk(0x02)))

    /** A USB keyboard: not serial. */
    fun keyboard(name: String = "/dev/bus/usb/001/004") = device(name, 0x046D, 0xC31C, 0x00, usbInterface(0, 0x03, 0x01, 0x01, interrupt(0x81)))
}
