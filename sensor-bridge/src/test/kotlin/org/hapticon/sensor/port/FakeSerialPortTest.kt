package org.hapticon.sensor.port

import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Assert.fail
import org.junit.Test
import java.io.IOException
import java.util.concurrent.atomic.AtomicInteger
import java.util.concurrent.atomic.AtomicReference
import org.hapticon.testing.FakeSerialPort

class FakeSerialPortTest {
    private val port = FakeSerialPort()
    private val buffer = ByteArray(16)

    private fun bytes(vararg values: Int) = ByteArray(values.size) { values[it].toByte() }

    private fun read(length: Int = buffer.size): ByteArray {
        val n = port.read(buffer, 0, length, timeoutMillis = 0)
        return if (n <= 0) ByteArray(0) else buffer.copyOf(n)
    }

    private inline fun <reified T : Throwable> assertThrows(block: () -> Unit): T {
        try {
            block()
        } catch (e: Throwable) {
            if (e is T) return e
            throw AssertionError("expected ${T::class.simpleName}, got $e", e)
        }
        throw AssertionError("expected ${T::class.simpleName}, nothing thrown")
    }

    @Test
    fun read_scriptedChunks_returnedOnePerRead() {
        port.enqueue(bytes(1, 2, 3, 4, 5), chunkSize = 2).enqueueChunks(bytes(6, 7, 8, 9), intArrayOf(1, 3))
        assertArrayEquals(bytes(1, 2), read())
        assertArrayEquals(bytes(3, 4), read())
        assertArrayEquals(bytes(5), read())
        assertArrayEquals(bytes(6), read())
        assertArrayEquals(bytes(7, 8, 9), read())
        assertEquals(5, port.readCount)
    }

    @Test
    fun read_chunkLargerThanRequest_restComesNext() {
        port.enqueue(bytes(1, 2, 3, 4, 5))
        assertArrayEquals(bytes(1, 2), read(2))
        assertArrayEquals(bytes(3, 4, 5), read())
    }

    @Test
    fun read_atOffset_writesThere() {
        port.enqueue(bytes(9, 8))
        assertEquals(2, port.read(buffer, 5, 3, 0))
        assertArrayEquals(bytes(0, 0, 0, 0, 0, 9, 8, 0), buffer.copyOf(8))
    }

    @Test
    fun read_scriptedTimeoutAndEnd_returnZeroThenMinusOneForEver() {
        port.enqueueTimeout().enqueue(bytes(1)).enqueueEnd()
        assertEquals(0, port.read(buffer, 0, 16, 0))
        assertEquals(1, port.read(buffer, 0, 16, 0))
        assertEquals(-1, port.read(buffer, 0, 16, 0))
        assertEquals(-1, port.read(buffer, 0, 16, 0))
        assertTrue(port.isOpen)
    }

    @Test
    fun read_emptyScript_timesOutWithZero() {
        assertEquals(0, port.read(buffer, 0, 16, timeoutMillis = 1))
    }

    @Test
    fun read_scriptedUnplug_throwsDisconnectedAndPortIsGone() {
        port.enqueue(bytes(1)).enqueueUnplug().enqueue(bytes(2))
        assertArrayEquals(bytes(1), read())
        assertThrows<PortDisconnectedException> { read() }
        assertFalse(port.isOpen)
        assertThrows<PortDisconnectedException> { read() }
        assertThrows<PortDisconnectedException> { port.write(bytes(1), 0, 1, 100) }
        assertThrows<PortDisconnectedException> { port.configure(LineSettings()) }
    }

    @Test
    fun read_scriptedFailure_throwsItOnceAndPortStaysOpen() {
        val failure = IOException("babble")
        port.enqueueFailure(failure).enqueue(bytes(3))
        assertEquals(failure, assertThrows<IOException> { read() })
        assertTrue(port.isOpen)
        assertArrayEquals(bytes(3), read())
    }

    @Test
    fun close_thenReadOrWrite_throwsIOExceptionNotDisconnected() {
        port.enqueue(bytes(1))
        port.close()
        assertFalse(port.isOpen)
        val e = assertThrows<IOException> { read() }
        assertFalse(e is PortDisconnectedException)
        assertFalse(assertThrows<IOException> { port.write(bytes(1), 0, 1, 100) } is PortDisconnectedException)
    }

    @Test
    fun unplug_readWaitingForEver_wakesWithDisconnect() {
        val outcome = AtomicReference<Throwable?>()
        val reader = Thread {
            try {
                port.read(buffer, 0, buffer.size, timeoutMillis = 0)
            } catch (e: Throwable) {
                outcome.set(e)
            }
        }
        reader.start()
        while (port.readCount == 0) Thread.yield()
        port.unplug()
        reader.join(60_000)
        assertFalse("reader still blocked", reader.isAlive)
        assertTrue(outcome.get().toString(), outcome.get() is PortDisconnectedException)
    }

    @Test
    fun enqueue_fromAnotherThread_wakesAWaitingRead() {
        val got = AtomicInteger(-2)
        val reader = Thread { got.set(port.read(ByteArray(8), 0, 8, timeoutMillis = 0)) }
        reader.start()
        while (port.readCount == 0) Thread.yield()
        port.enqueue(bytes(1, 2, 3))
        reader.join(60_000)
        assertEquals(3, got.get())
    }

    @Test
    fun write_twoCalls_recordedSeparately() {
        port.write(bytes(1, 2, 3), 1, 2, 100)
        port.write(bytes(4), 0, 1, 100)
        assertArrayEquals(bytes(2, 3, 4), port.writtenBytes())
        assertEquals(listOf(listOf<Byte>(2, 3), listOf<Byte>(4)), port.writes().map { it.toList() })
    }

    @Test
    fun write_pastTheStallPoint_recordsWhatFitAndTimesOut() {
        port.stallWritesAfter(4)
        port.write(bytes(1, 2, 3), 0, 3, 100)
        val e = assertThrows<PortTimeoutException> { port.write(bytes(4, 5, 6), 0, 3, 100) }
        assertEquals("wrote 1 of 3 bytes before the 100 ms deadline", e.message)
        assertArrayEquals(bytes(1, 2, 3, 4), port.writtenBytes())
        assertThrows<PortTimeoutException> { port.write(bytes(7), 0, 1, 100) }
        assertTrue(port.isOpen)
    }

    @Test
    fun write_pastTheStallPointWithoutDeadline_waitsUntilUnplugged() {
        port.stallWritesAfter(1)
        val outcome = AtomicReference<Throwable?>()
        val writer = Thread {
            try {
                port.write(bytes(1, 2), 0, 2, timeoutMillis = 0)
            } catch (e: Throwable) {
                outcome.set(e)
            }
        }
        writer.start()
        while (port.stalledWrites == 0) Thread.yield()
        port.unplug()
        writer.join(60_000)
        assertFalse("writer still blocked", writer.isAlive)
        assertTrue(outcome.get().toString(), outcome.get() is PortDisconnectedException)
        assertArrayEquals(bytes(1), port.writtenBytes())
    }

    @Test
    fun configure_settings_recorded() {
        val settings = LineSettings(baudRate = 1_000_000, dtr = false)
        port.configure(settings)
        assertEquals(settings, port.lineSettings)
    }

    @Test
    fun arguments_outOfRange_throw() {
        assertThrows<IndexOutOfBoundsException> { port.read(buffer, 10, 7, 0) }
        assertThrows<IllegalArgumentException> { port.read(buffer, 0, 1, -1) }
        assertThrows<IndexOutOfBoundsException> { port.write(buffer, -1, 1, 0) }
        assertThrows<IllegalArgumentException> { port.enqueue(bytes(1), chunkSize = 0) }
        assertThrows<IllegalArgumentException> { port.stallWritesAfter(-1) }
        try {
            port.enqueueChunks(bytes(1), IntArray(0))
            fail("accepted no chunk sizes")
        } catch (e: IllegalArgumentException) {
            // expected
        }
    }
}
