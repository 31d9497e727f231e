package org.hapticon.sensor.usb

import android.content.Context
import androidx.test.core.app.ApplicationProvider
import org.hapticon.sensor.serial.ProbeTable
import org.junit.Assert.assertEquals
import org.junit.Assert.assertTrue
import org.junit.Test
import org.junit.runner.RunWith
import org.robolectric.RobolectricTestRunner
import org.xmlpull.v1.XmlPullParser

@RunWith(RobolectricTestRunner::class)
class DeviceFilterTest {
    private val context = ApplicationProvider.getApplicationContext<Context>()

    /** The usb-device entries of res/xml/device_filter.xml as attribute maps. */
    private fun entries(): List<Map<String, String>> {
        val parser = context.resources.getXml(R.xml.device_filter)
        val found = mutableListOf<Map<String, String>>()
        while (parser.next() != XmlPullParser.END_DOCUMENT) {
            if (parser.eventType == XmlPullParser.START_TAG && parser.name == "usb-device") {
                found += (0 until parser.attributeCount).associate { parser.getAttributeName(it) to parser.getAttributeValue(it) }
            }
        }
        return found
    }

    @Test
    fun deviceFilter_listsTheSupportedVendorsAndTheCdcClass() {
        val vendors = entries().mapNotNull { it["vendor-id"]?.toInt() }.toSet()
        val classes = entries().mapNotNull { it["class"]?.toInt() }

        assertEquals(setOf(0x2341, 0x2A03, 0x16C0, 0x0403, 0x10C4, 0x1A86, 0x303A, 0x2E8A, 0x239A, 0x1B4F), vendors)
        assertEquals(listOf(2), classes)
    }

    @Test
    fun deviceFilter_coversEveryVendorOfTheProbeTable() {
        val vendors = entries().mapNotNull { it["vendor-id"]?.toInt() }.toSet()

        val missing = ProbeTable.default().vendorIds - vendors

        assertTrue("vendors in the probe table but not in device_filter.xml: $missing", missing.isEmpty())
    }
}
