package org.hapticon.sensor.serial

import org.hapticon.sensor.port.PortDisconnectedException
import org.hapticon.sensor.port.PortTimeoutException
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.fail
import org.junit.Test
import java.io.IOException

/** The shared read/write/close behaviour, through the simplest driver (CDC ACM, 64-byte packets). */
class UsbSerialPortTest {
    private val transport = FakeUsbTransport()
    private val port = CdcAcmDriver(TestDevices.arduinoUno).openPort(transport, clock = transport.clock)

    private inline fun <reified T : Throwable> thrownBy(block: () -> Unit): T {
        try {
            block()
        } catch (e: Throwable) {
            if (e is T) return e
            throw AssertionError("expected ${T::class.simpleName}, got $e", e)
        }
        throw AssertionError("expected ${T::class.simpleName}, nothing was thrown")
    }

    @Test
    fun read_dataArrives_copiesItAtTheOffset() {
        transport.incoming += Incoming.Data(bytes(1, 2, 3))
        val buffer = ByteArray(8)

        val count = port.read(buffer, offset = 4, length = 4, timeoutMillis = 100)

        assertEquals(3, count)
        assertArrayEquals(bytes(0, 0, 0, 0, 1, 2, 3, 0), buffer)
    }

    @Test
    fun read_nothingBeforeTheTimeoutWithDeviceAttached_returnsZeroAfterOneStatusCheck() {
        val count = port.read(ByteArray(16), timeoutMillis = 100)

        assertEquals(0, count)
        assertEquals(1, transport.statusChecks)
        assertEquals(listOf(BulkCall(0x83, 64, 100)), transport.bulkInCalls)
    }

    @Test
    fun read_unplugMidRead_throwsDisconnectedAndThePortIsNoLongerOpen() {
        transport.incoming += Incoming.Data(bytes(0x61, 0x62))
        transport.incoming += Incoming.Unplug
        val buffer = ByteArray(16)

        val first = port.read(buffer, timeoutMillis = 100)
        val error = thrownBy<PortDisconnectedException> { port.read(buffer, timeoutMillis = 100) }

        assertEquals(2, first)
        assertEquals("USB device 2341:0043 was unplugged", error.message)
        assertFalse(port.isOpen)
        thrownBy<PortDisconnectedException> { port.write(bytes(1), timeoutMillis = 100) }
    }

    @Test
    fun read_unplugDuringAReadWithoutTimeout_throwsDisconnected() {
        transport.incoming += Incoming.Unplug

        thrownBy<PortDisconnectedException> { port.read(ByteArray(16)) }
    }

    @Test
    fun read_transferFailsWithoutTimeoutAndDeviceAttached_throwsIOExceptionNotDisconnected() {
        val failing = object : UsbTransport by transport {
            override fun bulkTransfer(endpoint: UsbEndpointDescription, buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int) = -1
        }
        val failingPort = CdcAcmDriver(TestDevices.arduinoUno).openPort(failing, clock = transport.clock)

        val error = thrownBy<IOException> { failingPort.read(ByteArray(16)) }

        assertEquals(IOException::class.java, error.javaClass)
        assertEquals("Read from 2341:0043 failed with the device attached", error.message)
    }

    @Test
    fun read_zeroLengthPacketThenData_returnsTheData() {
        transport.incoming += Incoming.ZeroLength
        transport.incoming += Incoming.Data(bytes(9))
        val buffer = ByteArray(4)

        assertEquals(1, port.read(buffer, timeoutMillis = 100))
        assertEquals(9.toByte(), buffer[0])
    }

    @Test
    fun read_afterOnDeviceDetached_throwsDisconnectedWithoutATransfer() {
        port.onDeviceDetached()

        thrownBy<PortDisconnectedException> { port.read(ByteArray(4), timeoutMillis = 100) }
        assertEquals(emptyList<BulkCall>(), transport.bulkInCalls)
    }

    @Test
    fun read_afterClose_throwsIOExceptionNotDisconnected() {
        port.close()

        val error = thrownBy<IOException> { port.read(ByteArray(4), timeoutMillis = 100) }

        assertEquals("Port 0 of 2341:0043 is closed", error.message)
    }

    @Test
    fun read_tenByteBuffer_asksForOnePacketAndKeepsTheRest() {
        transport.incoming += Incoming.Data(ramp(64))
        val buffer = ByteArray(10)
        val rest = ByteArray(64)

        val first = port.read(buffer, timeoutMillis = 100)
        val second = port.read(rest, timeoutMillis = 100)

        assertEquals(listOf(BulkCall(0x83, 64, 100)), transport.bulkInCalls)
        assertEquals(10, first)
        assertEquals(54, second)
        assertArrayEquals(ramp(64), buffer + rest.copyOf(54))
    }

    @Test
    fun read_largeBuffer_asksForOnePacketSoATimeoutCannotDropReceivedData() {
        transport.incoming += Incoming.Data(ramp(64))

        val count = port.read(ByteArray(1024), timeoutMillis = 100)

        assertEquals(64, count)
        assertEquals(listOf(BulkCall(0x83, 64, 100)), transport.bulkInCalls)
    }

    @Test
    fun write_150Bytes_sendsChunksOfTheMaxPacketSize() {
        port.write(ramp(150), timeoutMillis = 100)

        assertEquals(listOf(64, 64, 22), transport.bulkOutCalls.map { it.length })
        assertArrayEquals(ramp(150), transport.writtenBytes())
    }

    @Test
    fun write_offsetAndLength_sendOnlyThatRange() {
        port.write(ramp(10), offset = 2, length = 3, timeoutMillis = 100)

        assertArrayEquals(bytes(2, 3, 4), transport.writtenBytes())
    }

    @Test
    fun write_deviceAcceptsSlowly_throwsTimeoutOnceTheOneDeadlineHasPassed() {
        transport.onWrite = { _, _ ->
            transport.clock.advance(30)
            10
        }

        val error = thrownBy<PortTimeoutException> { port.write(ramp(200), timeoutMillis = 100) }

        assertEquals("Wrote 40 of 200 bytes to 2341:0043 before the 100 ms deadline", error.message)
        assertEquals("each chunk gets only the time left", listOf(100, 70, 40, 10), transport.bulkOutCalls.map { it.timeoutMillis })
        assertEquals(listOf(64, 64, 64, 64), transport.bulkOutCalls.map { it.length })
    }

    @Test
    fun write_chunkTimesOutWithDeviceAttached_throwsTimeout() {
        transport.onWrite = { length, timeout ->
            if (transport.bulkOutCalls.size == 1) {
                length
            } else {
                transport.clock.advance(timeout)
                -1
            }
        }

        val error = thrownBy<PortTimeoutException> { port.write(ramp(100), timeoutMillis = 50) }

        assertEquals("Wrote 64 of 100 bytes to 2341:0043 before the 50 ms deadline", error.message)
    }

    @Test
    fun write_transferFailsEarlyWithDeviceAttached_throwsIOExceptionNotTimeout() {
        transport.onWrite = { _, _ -> -1 }

        val error = thrownBy<IOException> { port.write(ramp(10), timeoutMillis = 50) }

        assertEquals(IOException::class.java, error.javaClass)
        assertEquals("Write to 2341:0043 failed after 0 of 10 bytes", error.message)
    }

    @Test
    fun write_deviceUnplugged_throwsDisconnected() {
        transport.attached = false

        thrownBy<PortDisconnectedException> { port.write(ramp(10), timeoutMillis = 50) }
    }

    @Test
    fun write_nothing_sendsNoTransfer() {
        port.write(ByteArray(0), timeoutMillis = 50)

        assertEquals(emptyList<BulkCall>(), transport.bulkOutCalls)
    }

    @Test
    fun read_bufferRangeOutsideTheArray_throwsIndexOutOfBounds() {
        thrownBy<IndexOutOfBoundsException> { port.read(ByteArray(4), offset = 2, length = 3, timeoutMillis = 10) }
    }

    @Test
    fun close_afterUnplug_doesNotTouchTheDevice() {
        port.onDeviceDetached()

        port.close()

        assertEquals(emptyList<Int>(), transport.released)
        assertFalse(port.isOpen)
    }

    @Test
    fun read_timeoutsPassedToTheTransfer_shrinkAcrossZeroLengthPackets() {
        val stepping = object : UsbTransport by transport {
            override fun bulkTransfer(endpoint: UsbEndpointDescription, buffer: ByteArray, offset: Int, length: Int, timeoutMillis: Int): Int {
                transport.bulkInCalls += BulkCall(endpoint.address, length, timeoutMillis)
                transport.clock.advance(25)
                return 0
            }
        }
        val steppingPort = CdcAcmDriver(TestDevices.arduinoUno).openPort(stepping, clock = transport.clock)

        val count = steppingPort.read(ByteArray(8), timeoutMillis = 60)

        assertEquals(0, count)
        assertEquals(listOf(60, 35, 10), transport.bulkInCalls.map { it.timeoutMillis })
    }
}
