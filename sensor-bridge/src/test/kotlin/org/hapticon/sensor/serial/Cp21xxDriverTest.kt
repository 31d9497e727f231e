package org.hapticon.sensor.serial

import org.hapticon.sensor.port.UnsupportedSettingException
import org.hapticon.sensor.port.LineSettings
import org.hapticon.sensor.port.Parity
import org.hapticon.sensor.port.PortDisconnectedException
import org.hapticon.sensor.port.StopBits
import org.junit.Assert.assertEquals
import org.junit.Assert.fail
import org.junit.Test

class Cp21xxDriverTest {
    private val transport = FakeUsbTransport()

    @Test
    fun openPort_cp2102_enablesUartThen115200_8N1AndRaisesDtrRts() {
        Cp21xxDriver(TestDevices.cp2102).openPort(transport)

        assertEquals(listOf(0), transport.claimed)
        assertEquals(
            listOf(
                ControlCall(0x41, 0x00, 0x0001, 0),
                ControlCall(0x41, 0x1E, 0x0000, 0, ints(0x00, 0xC2, 0x01, 0x00)),
                ControlCall(0x41, 0x03, 0x0800, 0),
                ControlCall(0x41, 0x07, 0x0303, 0),
            ),
            transport.controlCalls,
        )
    }

    @Test
    fun configure_7E2DtrOnly_encodesLineControlAndHandshake() {
        val port = Cp21xxDriver(TestDevices.cp2102).openPort(transport)
        transport.controlCalls.clear()

        port.configure(LineSettings(baudRate = 921_600, dataBits = 7, parity = Parity.EVEN, stopBits = StopBits.TWO, rts = false))

        assertEquals(
            listOf(
                ControlCall(0x41, 0x1E, 0x0000, 0, ints(0x00, 0x10, 0x0E, 0x00)),
                ControlCall(0x41, 0x03, 0x0722, 0),
                ControlCall(0x41, 0x07, 0x0301, 0),
            ),
            transport.controlCalls,
        )
    }

    @Test
    fun openPort_secondPortOfCp2105_addressesInterface1() {
        Cp21xxDriver(TestDevices.cp2105).openPort(transport, portIndex = 1)

        assertEquals(listOf(1), transport.claimed)
        assertEquals(listOf(1, 1, 1, 1), transport.controlCalls.map { it.index })
    }

    @Test
    fun configure_baudRateTheChipStalls_throwsUnsupportedSetting() {
        val port = Cp21xxDriver(TestDevices.cp2105).openPort(transport, portIndex = 1)
        transport.controlResults[0x1E] = -1

        try {
            port.configure(LineSettings(baudRate = 1_000_000))
            fail("accepted a stalled baud rate")
        } catch (e: UnsupportedSettingException) {
            assertEquals("CP210x on 10c4:ea70 rejected 1000000 baud", e.message)
        }
        assertEquals(LineSettings(), port.lineSettings)
    }

    @Test
    fun configure_baudRateFailsBecauseTheDeviceIsGone_throwsDisconnected() {
        val port = Cp21xxDriver(TestDevices.cp2102).openPort(transport)
        transport.attached = false

        try {
            port.configure(LineSettings(baudRate = 9600))
            fail("configured an unplugged device")
        } catch (e: PortDisconnectedException) {
            assertEquals("USB device 10c4:ea60 was unplugged", e.message)
        }
    }

    @Test
    fun configure_oneAndAHalfStopBitsOrAbove3Mbaud_throwsUnsupportedAndSendsNothing() {
        val port = Cp21xxDriver(TestDevices.cp2102).openPort(transport)
        transport.controlCalls.clear()

        val messages = listOf(LineSettings(stopBits = StopBits.ONE_POINT_FIVE), LineSettings(baudRate = 4_000_000)).map {
            try {
                port.configure(it)
                "accepted"
            } catch (e: UnsupportedSettingException) {
                e.message
            }
        }

        assertEquals(listOf("CP210x chips do not do 1.5 stop bits", "CP210x chips run at most 3000000 baud, not 4000000"), messages)
        assertEquals(emptyList<ControlCall>(), transport.controlCalls)
    }

    @Test
    fun close_disablesTheUartAndReleasesTheInterface() {
        val port = Cp21xxDriver(TestDevices.cp2102).openPort(transport)
        transport.controlCalls.clear()

        port.close()

        assertEquals(listOf(ControlCall(0x41, 0x00, 0x0000, 0)), transport.controlCalls)
        assertEquals(listOf(0), transport.released)
    }
}
