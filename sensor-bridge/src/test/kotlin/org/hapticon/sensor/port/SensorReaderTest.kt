package org.hapticon.sensor.port

import org.hapticon.sensor.protocol.stream.FrameError
import org.hapticon.sensor.protocol.stream.StreamDecoder
import org.hapticon.sensor.protocol.framed.FramedDecoder
import org.hapticon.sensor.protocol.framed.SampleFrame
import org.hapticon.sensor.protocol.stream.StreamStats
import org.hapticon.testing.RecordedStreams
import org.junit.Assert.assertEquals
import org.junit.Assert.assertFalse
import org.junit.Assert.assertNull
import org.junit.Assert.assertSame
import org.junit.Assert.assertTrue
import org.junit.Test
import java.io.IOException
import java.util.Collections
import org.hapticon.testing.FakeSerialPort

class SensorReaderTest {
    /** Frames and the stop event, in the order the reading thread produced them. */
    private val log: MutableList<String> = Collections.synchronizedList(ArrayList())
    private var stopCause: Throwable? = null

    private val frames = object : FramedDecoder.Listener {
        override fun onSample(frame: SampleFrame) {
            log += "sample ${frame.sequence}"
        }
    }

    private val stopped = SensorReader.Listener { reason, cause ->
        stopCause = cause
        log += "stopped $reason"
    }

    private fun samples(vararg sequences: Int) = sequences.map { "sample $it" }

    @Test
    fun run_unplugMidFrame_deliversEveryWholeFrameThenReportsDisconnect() {
        val port = FakeSerialPort().enqueue(RecordedStreams.bytes(RecordedStreams.FRAMED_UNPLUG), chunkSize = 7).enqueueUnplug()
        val decoder = FramedDecoder(frames)
        val reason = SensorReader(port, decoder, stopped).run()
        assertEquals(SensorReader.StopReason.DISCONNECTED, reason)
        assertEquals(samples(1, 2, 3, 4, 5, 6, 7, 8, 9, 10) + "stopped DISCONNECTED", log)
        assertTrue(stopCause is PortDisconnectedException)
        assertEquals(1L, decoder.stats.badFrames(FrameError.TRUNCATED))
        assertEquals(9L, decoder.stats.droppedBytes)
    }

    @Test
    fun run_replayWithSplitReads_endOfStreamAfterEveryFrame() {
        val port = ReplayPort(RecordedStreams.open(RecordedStreams.FRAMED_SPLIT_READS), RecordedStreams.splitReadSizes())
        val decoder = FramedDecoder(frames)
        assertEquals(SensorReader.StopReason.END_OF_STREAM, SensorReader(port, decoder, stopped, bufferSize = 64).run())
        assertEquals(samples(*(1..30).toList().toIntArray()) + "stopped END_OF_STREAM", log)
        assertNull(stopCause)
        assertEquals(0L, decoder.stats.droppedBytes)
    }

    @Test
    fun run_readTimeouts_doNotEndTheLoop() {
        val wire = RecordedStreams.bytes(RecordedStreams.FRAMED_CLEAN)
        val port = FakeSerialPort().enqueueTimeout().enqueue(wire.copyOf(100)).enqueueTimeout().enqueueTimeout()
            .enqueue(wire.copyOfRange(100, wire.size)).enqueueEnd()
        val decoder = FramedDecoder(frames)
        assertEquals(SensorReader.StopReason.END_OF_STREAM, SensorReader(port, decoder, stopped).run())
        assertEquals(20L, log.count { it.startsWith("sample") }.toLong())
        assertEquals(22L, decoder.stats.frames)
    }

    @Test
    fun run_transferError_failedWithTheCause() {
        val error = IOException("pipe stalled")
        // framed-clean.bin: a delimiter (1 byte), device info (35), then 22-byte samples: 60 bytes hold sample 1.
        val port = FakeSerialPort().enqueue(RecordedStreams.bytes(RecordedStreams.FRAMED_CLEAN).copyOf(60)).enqueueFailure(error)
        assertEquals(SensorReader.StopReason.FAILED, SensorReader(port, FramedDecoder(frames), stopped).run())
        assertSame(error, stopCause)
        assertEquals(samples(1) + "stopped FAILED", log)
    }

    @Test
    fun run_listenerThrows_failedWithTheCauseAndNoMoreFrames() {
        val boom = IllegalStateException("listener bug")
        val decoder = FramedDecoder(object : FramedDecoder.Listener {
            override fun onSample(frame: SampleFrame) {
                log += "sample ${frame.sequence}"
                if (frame.sequence == 2) throw boom
            }
        })
        val port = FakeSerialPort().enqueue(RecordedStreams.bytes(RecordedStreams.FRAMED_CLEAN)).enqueueEnd()
        assertEquals(SensorReader.StopReason.FAILED, SensorReader(port, decoder, stopped).run())
        assertSame(boom, stopCause)
        assertEquals(samples(1, 2) + "stopped FAILED", log)
    }

    @Test
    fun start_thenStop_endsWithStoppedOnItsOwnThread() {
        val port = FakeSerialPort() // nothing to read: every read times out
        val threads = Collections.synchronizedList(ArrayList<String>())
        val reader = SensorReader(port, FramedDecoder(frames), { reason, _ ->
            threads += Thread.currentThread().name
            log += "stopped $reason"
        }, readTimeoutMillis = 1)
        reader.start(threadName = "test-reader")
        while (port.readCount < 3) Thread.yield()
        assertTrue(reader.isRunning)
        reader.stop()
        assertTrue("did not stop", reader.awaitStop(60_000))
        assertFalse(reader.isRunning)
        assertEquals(listOf("stopped STOPPED"), log)
        assertEquals(listOf("test-reader"), threads)
        assertTrue(port.isOpen) // the port belongs to the caller
    }

    @Test
    fun start_unplugWhileWaiting_reportsDisconnected() {
        val port = FakeSerialPort()
        val reader = SensorReader(port, FramedDecoder(frames), stopped, readTimeoutMillis = 60_000)
        reader.start()
        port.enqueue(RecordedStreams.bytes(RecordedStreams.FRAMED_CLEAN).copyOf(100))
        while (port.readCount < 2) Thread.yield()
        port.unplug()
        assertTrue("did not stop", reader.awaitStop(60_000))
        assertEquals("stopped DISCONNECTED", log.last())
        assertEquals(samples(1, 2), log.filter { it.startsWith("sample") }) // 100 bytes: 1 + 35 + 2 × 22 + 20
    }

    @Test
    fun start_threadSetup_runsOnTheReaderThreadBeforeTheFirstRead() {
        val port = FakeSerialPort().enqueue(RecordedStreams.bytes(RecordedStreams.FRAMED_CLEAN).copyOf(58)).enqueueEnd()
        val setupSaw = Collections.synchronizedList(ArrayList<String>())
        val reader = SensorReader(port, FramedDecoder(frames), { reason, _ -> log += "stopped $reason on ${Thread.currentThread().name}" }, threadSetup = {
            setupSaw += "setup on ${Thread.currentThread().name} after ${port.readCount} reads"
            log += "setup"
        })
        reader.start(threadName = "test-reader")
        assertTrue("did not stop", reader.awaitStop(60_000))
        assertEquals(listOf("setup on test-reader after 0 reads"), setupSaw)
        // 58 bytes: 1 + 35 + one 22-byte sample (as in start_unplugWhileWaiting); the setup came before the first frame.
        assertEquals(listOf("setup", "sample 1", "stopped END_OF_STREAM on test-reader"), log)
    }

    @Test
    fun run_threadSetupThrows_failsBeforeAnyRead() {
        val port = FakeSerialPort().enqueue(RecordedStreams.bytes(RecordedStreams.FRAMED_CLEAN))
        val refused = SecurityException("priority refused")
        val reason = SensorReader(port, FramedDecoder(frames), stopped, threadSetup = { throw refused }).run()
        assertEquals(SensorReader.StopReason.FAILED, reason)
        assertSame(refused, stopCause)
        assertEquals(0, port.readCount)
        assertEquals(listOf("stopped FAILED"), log)
    }

    @Test
    fun awaitStop_neverStarted_isTrueAtOnce() {
        assertTrue(SensorReader(FakeSerialPort(), FramedDecoder(frames), stopped).awaitStop(0))
    }

    @Test
    fun awaitStop_stillRunning_falseAfterTheLimit() {
        val reader = SensorReader(FakeSerialPort(), FramedDecoder(frames), stopped, readTimeoutMillis = 1)
        reader.start()
        assertFalse(reader.awaitStop(0))
        reader.stop()
        assertTrue(reader.awaitStop(60_000))
    }

    @Test
    fun runOrStart_secondTime_throws() {
        val reader = SensorReader(FakeSerialPort().enqueueEnd(), FramedDecoder(frames), stopped)
        reader.run()
        for (again in listOf<() -> Unit>({ reader.run() }, { reader.start() })) {
            try {
                again()
                throw AssertionError("ran twice")
            } catch (e: IllegalStateException) {
                // expected
            }
        }
    }

    @Test
    fun stop_beforeRun_endsAfterNoRead() {
        val port = FakeSerialPort().enqueue(byteArrayOf(1, 2, 3))
        val decoder = object : StreamDecoder {
            override val stats = StreamStats()
            override fun feed(bytes: ByteArray, offset: Int, length: Int) {
                log += "feed $length"
            }

            override fun finish() {
                log += "finish"
            }
        }
        val reader = SensorReader(port, decoder, stopped)
        reader.stop()
        assertEquals(SensorReader.StopReason.STOPPED, reader.run())
        assertEquals(listOf("finish", "stopped STOPPED"), log)
        assertEquals(0, port.readCount)
    }

    @Test
    fun constructor_nonPositiveTimeoutOrBuffer_throws() {
        for (make in listOf<() -> Unit>(
            { SensorReader(FakeSerialPort(), FramedDecoder(frames), stopped, readTimeoutMillis = 0) },
            { SensorReader(FakeSerialPort(), FramedDecoder(frames), stopped, bufferSize = 0) },
        )) {
            try {
                make()
                throw AssertionError("accepted")
            } catch (e: IllegalArgumentException) {
                // expected
            }
        }
    }
}
