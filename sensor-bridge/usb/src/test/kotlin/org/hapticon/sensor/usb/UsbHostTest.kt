package org.hapticon.sensor.usb

import android.content.Context
import android.content.pm.PackageManager
import androidx.test.core.app.ApplicationProvider
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.robolectric.Shadows.shadowOf

@RunWith(RobolectricTestRunner::class)
class UsbHostTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()

    @Test
    fun hasUsbHost_followsTheSystemFeature() {
        shadowOf(context.packageManager).setSystemFeature(PackageManager.FEATURE_USB_HOST, false)
        assertFalse(hasUsbHost(context))
        shadowOf(context.packageManager).setSystemFeature(PackageManager.FEATURE_USB_HOST, true)
        assertTrue(hasUsbHost(context))
    }

    @Test
    fun deviceFilter_isPackagedWithTheLibrary() {
        val id = context.resources.getIdentifier("device_filter", "xml", context.packageName)
        assertTrue("device_filter.xml resource id", id != 0)
    }
}
