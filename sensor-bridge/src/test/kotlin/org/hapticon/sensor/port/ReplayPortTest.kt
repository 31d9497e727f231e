package org.hapticon.sensor.port

import org.hapticon.testing.RecordedStreams
import org.junit.Assert.assertArrayEquals
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertTrue
import org.junit.Test
import java.io.ByteArrayInputStream
import java.io.ByteArrayOutputStream
import java.io.File
import java.io.IOException

class ReplayPortTest {
    private fun bytes(vararg values: Int) = ByteArray(values.size) { values[it].toByte() }

    private fun readAll(port: SerialPort, bufferSize: Int = 256): List<Int> {
        val buffer = ByteArray(bufferSize)
        val sizes = ArrayList<Int>()
        while (true) {
            val n = port.read(buffer, 0, buffer.size, 100)
            sizes += n
            if (n < 0) return sizes
        }
    }

    @Test
    fun replay_twoReadSizes_cycleAndEndWithMinusOne() {
        val port = ReplayPort(ByteArrayInputStream(ByteArray(20)), intArrayOf(3, 5))
        assertEquals(listOf(3, 5, 3, 5, 3, 1, -1), readAll(port))
        assertEquals(-1, port.read(ByteArray(4), 0, 4, 0))
    }

    @Test
    fun replay_requestSmallerThanReadSize_givesTheRequest() {
        val port = ReplayPort(ByteArrayInputStream(bytes(1, 2, 3, 4)))
        val buffer = ByteArray(4)
        assertEquals(2, port.read(buffer, 1, 2, 0))
        assertArrayEquals(bytes(0, 1, 2, 0), buffer)
        assertEquals(0, port.read(buffer, 0, 0, 0))
    }

    @Test
    fun replay_recordedStreamWithItsReadPlan_returnsEveryByteInThosePieces() {
        val expected = RecordedStreams.bytes(RecordedStreams.FRAMED_SPLIT_READS)
        val plan = RecordedStreams.splitReadSizes()
        val port = ReplayPort(RecordedStreams.open(RecordedStreams.FRAMED_SPLIT_READS), plan)
        val out = ByteArrayOutputStream()
        val buffer = ByteArray(128)
        var i = 0
        while (true) {
            val n = port.read(buffer, 0, buffer.size, 0)
            if (n < 0) break
            if (out.size() + n < expected.size) assertEquals(plan[i % plan.size], n)
            out.write(buffer, 0, n)
            i++
        }
        assertArrayEquals(expected, out.toByteArray())
    }

    @Test
    fun replay_fromFile_readsIt() {
        val file = File.createTempFile("hapticon-replay", ".bin")
        try {
            file.writeBytes(bytes(5, 6, 7))
            ReplayPort(file).use { port ->
                val buffer = ByteArray(8)
                assertEquals(3, port.read(buffer, 0, 8, 0))
                assertArrayEquals(bytes(5, 6, 7), buffer.copyOf(3))
            }
        } finally {
            file.delete()
        }
    }

    @Test
    fun replay_writeThenClose_writesCountedAndLaterCallsFail() {
        var closed = false
        val input = object : ByteArrayInputStream(ByteArray(4)) {
            override fun close() {
                closed = true
            }
        }
        val port = ReplayPort(input)
        port.write(bytes(1, 2, 3), 0, 3, 100)
        port.configure(LineSettings())
        assertEquals(3L, port.bytesWritten)
        port.close()
        assertTrue(closed)
        assertFalse(port.isOpen)
        for (call in listOf<() -> Unit>({ port.read(ByteArray(1), 0, 1, 0) }, { port.write(ByteArray(1), 0, 1, 0) }, { port.configure(LineSettings()) })) {
            try {
                call()
                throw AssertionError("worked after close")
            } catch (e: IOException) {
                assertFalse(e is PortDisconnectedException)
            }
        }
    }
}
