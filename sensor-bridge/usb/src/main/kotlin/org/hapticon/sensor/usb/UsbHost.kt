package org.hapticon.sensor.usb

import android.content.Context
import android.content.pm.PackageManager

/** Whether this phone can act as a USB host (OTG). */
fun hasUsbHost(context: Context): Boolean =
    context.packageManager.hasSystemFeature(PackageManager.FEATURE_USB_HOST)
