package org.hapticon.sensor.serial

/**
 * Finds the driver for a USB device: first by (vendor id, product id) in [table], then, for devices
 * not in it, by interface class: any device with a CDC ACM function gets [CdcAcmDriver].
 */
public class UsbSerialProber(private val table: ProbeTable = ProbeTable.default()) {
    /** The driver for [device], or null if it is not a serial device we can drive. */
    public fun probe(device: UsbDeviceDescription): UsbSerialDriver? =
        table.find(device) ?: if (CdcAcmDriver.isCdcAcm(device)) CdcAcmDriver(device) else null
}
