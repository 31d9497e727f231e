package org.hapticon.sensor.serial

import org.junit.Assert.assertEquals
import org.junit.Assert.assertNull
import org.junit.Assert.assertSame
import org.junit.Assert.fail
import org.junit.Test

class UsbSerialProberTest {
    private val prober = UsbSerialProber()

    private fun chipOf(device: UsbDeviceDescription): String? = prober.probe(device)?.chipFamily

    @Test
    fun probe_knownChips_pickTheirDriversFromTheTable() {
        assertEquals("FTDI", chipOf(TestDevices.ft232r))
        assertEquals("FTDI", chipOf(TestDevices.ft232h))
        assertEquals("CP210x", chipOf(TestDevices.cp2102))
        assertEquals("CH34x", chipOf(TestDevices.ch340))
        assertEquals("CDC-ACM", chipOf(TestDevices.arduinoUno))
    }

    @Test
    fun probe_unknownIdsWithCdcAcmInterfaces_fallsBackToTheClass() {
        assertEquals("CDC-ACM", chipOf(TestDevices.ch9102))
        assertEquals("CDC-ACM", chipOf(TestDevices.compositeCdc))
        assertEquals(2, prober.probe(TestDevices.dualCdc)?.portCount)
    }

    @Test
    fun probe_hidOrUnknownVendorSpecificDevice_isNull() {
        assertNull(prober.probe(TestDevices.keyboard))
        assertNull(prober.probe(TestDevices.ft232r.copy(vendorId = 0x1234)))
    }

    @Test
    fun probe_customTable_servesALabBoardWithAChosenDriver() {
        val labBoard = TestDevices.cp2102.copy(vendorId = 0x1209, productId = 0x0001)
        val custom = UsbSerialProber(ProbeTable.default().add(0x1209, 0x0001, ::Cp21xxDriver))

        assertEquals("CP210x", custom.probe(labBoard)?.chipFamily)
        assertNull(prober.probe(labBoard))
    }

    @Test
    fun find_driverKeepsTheDeviceItWasMadeFor() {
        val driver = ProbeTable.default().find(TestDevices.cp2105)

        assertSame(TestDevices.cp2105, driver?.device)
        assertEquals(2, driver?.portCount)
    }

    @Test
    fun add_sameIdsTwice_theLaterEntryWins() {
        val table = ProbeTable().add(0x0403, 0x6001, ::Cp21xxDriver).add(0x0403, 0x6001, ::FtdiDriver)

        assertEquals("FTDI", table.find(TestDevices.ft232r)?.chipFamily)
    }

    @Test
    fun add_idAbove16Bits_throwsIllegalArgument() {
        try {
            ProbeTable().add(0x10000, 1, ::FtdiDriver)
            fail("accepted a 17-bit vendor id")
        } catch (e: IllegalArgumentException) {
            assertEquals("ids must be 16-bit, were 65536:1", e.message)
        }
    }

    @Test
    fun vendorIds_defaultTable_areTheSevenVendorsOfDocsUsbMd() {
        assertEquals(setOf(0x0403, 0x10C4, 0x1A86, 0x2341, 0x16C0, 0x303A, 0x2E8A), ProbeTable.default().vendorIds)
    }
}
